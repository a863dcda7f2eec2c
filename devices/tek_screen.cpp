#include "devices/tek_screen.h"

#include <algorithm>

#include "devices/render.h"
#include "devices/tek_glyphs.h"

namespace igds {

namespace {

// Rows of the dialogue kept on a new page when the old one is full: enough to see the question
// being answered and the last replies.
constexpr int carried_rows = 3;

bool blank(char32_t c) {
  return c == U' ';
}

}  // namespace

std::u32string utf32(std::string_view s) {
  std::u32string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const auto b = static_cast<unsigned char>(s[i]);
    int extra = b < 0x80             ? 0
                : (b & 0xE0) == 0xC0 ? 1
                : (b & 0xF0) == 0xE0 ? 2
                : (b & 0xF8) == 0xF0 ? 3
                                     : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= s.size() + (extra == 0 ? 1 : 0)) {
      out += U'\uFFFD';
      ++i;
      continue;
    }
    char32_t c = extra == 0 ? b : (b & (0x3F >> extra));
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto t = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      if ((t & 0xC0) != 0x80) ok = false;
      c = (c << 6) | (t & 0x3F);
    }
    out += ok ? c : U'\uFFFD';
    i += ok ? static_cast<std::size_t>(extra) + 1 : 1;
  }
  return out;
}

std::string utf8(std::u32string_view text) {
  std::string out;
  for (char32_t c : text) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

namespace {

// Where the later rows of a paragraph start (lay_out).
std::size_t hang_of(const std::u32string& p, std::size_t columns) {
  std::size_t indent = 0;
  while (indent < p.size() && blank(p[indent])) ++indent;
  // A list's number: "1. ", "12) ".
  std::size_t i = indent;
  while (i < p.size() && p[i] >= U'0' && p[i] <= U'9') ++i;
  if (i > indent && i + 1 < p.size() && (p[i] == U'.' || p[i] == U')') && blank(p[i + 1])) {
    std::size_t text = i + 1;
    while (text < p.size() && blank(p[text])) ++text;
    return text;
  }
  // A term and its explanation, two blanks or more apart: the explanation's column, or four
  // more than the term's when that would leave less than half the row.
  const auto gap = indent > 0 ? p.find(U"  ", indent) : std::u32string::npos;
  if (gap == std::u32string::npos) return std::min(indent, columns / 2);
  std::size_t text = gap;
  while (text < p.size() && blank(p[text])) ++text;
  return text <= columns / 2 ? text : std::min(indent + 4, columns / 2);
}

}  // namespace

std::vector<std::string> lay_out(std::string_view paragraphs, int columns) {
  const auto width = static_cast<std::size_t>(std::max(columns, 8));
  std::vector<std::string> rows;
  // A text's last line end starts no empty line.
  if (paragraphs.ends_with('\n')) paragraphs.remove_suffix(1);
  if (paragraphs.empty()) return rows;
  const std::u32string all = utf32(paragraphs);
  std::size_t start = 0;
  while (start <= all.size()) {
    auto end = all.find(U'\n', start);
    if (end == std::u32string::npos) end = all.size();
    std::u32string p = all.substr(start, end - start);
    while (!p.empty() && blank(p.back())) p.pop_back();
    start = end + 1;
    if (p.size() <= width) {
      rows.push_back(utf8(p));
      if (end == all.size()) break;
      continue;
    }
    const std::size_t hang = hang_of(p, width);
    std::u32string row;
    std::size_t i = 0;
    while (i < p.size() && blank(p[i])) row += p[i++];
    while (i < p.size()) {
      std::size_t j = i;
      while (j < p.size() && !blank(p[j])) ++j;
      std::u32string_view word(p.data() + i, j - i);
      std::size_t k = j;
      while (k < p.size() && blank(p[k])) ++k;
      const std::u32string_view gap(p.data() + j, k - j);
      if (row.size() + word.size() > width && row.find_first_not_of(U' ') != std::u32string::npos) {
        while (!row.empty() && blank(row.back())) row.pop_back();
        rows.push_back(utf8(row));
        row.assign(hang, U' ');
      }
      while (row.size() + word.size() > width) {  // a word longer than a row is cut
        const std::size_t fits = width - std::min(width - 1, row.size());
        row += word.substr(0, fits);
        word.remove_prefix(fits);
        rows.push_back(utf8(row));
        row.assign(hang, U' ');
      }
      row += word;
      row += gap;
      i = k;
    }
    while (!row.empty() && blank(row.back())) row.pop_back();
    rows.push_back(utf8(row));
    if (end == all.size()) break;
  }
  return rows;
}

TekScreen::TekScreen(TekOptions tek, bool dialogue)
    : options_(tek),
      unit_(tek.bits == 12 ? 4 : 1),
      dialogue_(dialogue),
      tek_(tek.bits),
      layout_(dialogue ? dialogue_layout() : full_layout()) {}

TekScreen::Flow TekScreen::flow() const {
  const int columns = layout_.dialogue_columns > 0 ? layout_.dialogue_columns : text_columns;
  if (picture_ && !in_document_) return {0, layout_.dialogue_top, columns, layout_.dialogue_rows};
  return {0, tek_screen::text_top, columns, text_rows};
}

int TekScreen::rows_per_page() const {
  return flow().rows;
}

std::vector<std::u32string> TekScreen::wrap(const std::u32string& line, int columns, bool set_out) {
  std::vector<std::u32string> rows;
  const auto width = static_cast<std::size_t>(columns);
  if (set_out && line.size() > width) {
    // Set out in columns by whoever wrote it (an APL result): cut at the width, never broken at
    // a blank, so that its columns stay in line from one row to the next.
    for (std::size_t at = 0; at < line.size(); at += width) rows.push_back(line.substr(at, width));
    return rows;
  }
  std::u32string row;
  std::size_t i = 0;
  while (i < line.size()) {
    if (blank(line[i])) {
      std::size_t j = i;
      while (j < line.size() && blank(line[j])) ++j;
      // Blanks at a break are dropped; blanks that end the line are kept (a prompt's).
      if (row.size() + (j - i) > width && j < line.size()) {
        rows.push_back(row);
        row.clear();
      } else {
        row.append(line, i, std::min(j - i, width - std::min(width, row.size())));
      }
      i = j;
      continue;
    }
    std::size_t j = i;
    while (j < line.size() && !blank(line[j])) ++j;
    std::u32string_view word(line.data() + i, j - i);
    if (row.size() + word.size() > width && !row.empty()) {
      // The word goes to the next row; the blanks before it stay behind.
      while (!row.empty() && blank(row.back())) row.pop_back();
      rows.push_back(row);
      row.clear();
    }
    while (word.size() > width) {  // a word longer than a row is cut
      rows.emplace_back(word.substr(0, width));
      word.remove_prefix(width);
    }
    row += word;
    i = j;
  }
  rows.push_back(row);
  return rows;
}

int TekScreen::rows_of_lines() const {
  int n = 0;
  for (const auto& line : lines_)
    n += static_cast<int>(wrap(line, flow().columns, line.set_out).size());
  return n;
}

int TekScreen::rows_of(std::string_view line, bool set_out) const {
  return static_cast<int>(wrap(utf32(line), flow().columns, set_out).size());
}

int TekScreen::rows_left() const {
  return flow().rows - rows_of_lines();
}

void TekScreen::emit(int row, int column, std::u32string_view text) {
  const Flow f = flow();
  if (row >= f.rows) return;  // a line longer than the page shows its first rows only
  const int x = f.x + column * tek_screen::char_width;
  const int y = f.top - row * tek_screen::line_height;
  // The alpha cursor where the next character goes.
  draw_text(x, y, text);
  move_cursor(x + static_cast<int>(text.size()) * tek_screen::char_width, y);
}

void TekScreen::draw_text(int x, int y, std::u32string_view text) {
  // Runs of 7-bit characters in alpha mode; an APL symbol (the 4013 had them, xterm's Tek
  // window has not) drawn as strokes in its cell; anything else a question mark.
  std::string ascii;
  int run_x = x;
  auto flush = [&] {
    if (ascii.empty()) return;
    // Where the alpha cursor already is (the next character of a line being typed), nothing
    // needs to move it.
    if (!(cursor_ && *cursor_ == DevicePoint{run_x, y})) tek_.alpha_at(at(run_x, y));
    tek_.append_text(ascii);
    cursor_ = DevicePoint{run_x + static_cast<int>(ascii.size()) * tek_screen::char_width, y};
    ascii.clear();
  };
  for (char32_t c : text) {
    if (c >= 0x80 && has_tek_glyph(c)) {
      flush();
      draw_tek_glyph(tek_, at(x, y), c, unit_);
      cursor_.reset();
    } else {
      if (ascii.empty()) run_x = x;
      ascii += (c >= 0x20 && c < 0x7F) ? static_cast<char>(c) : '?';
    }
    x += tek_screen::char_width;
  }
  flush();
}

void TekScreen::draw_caption(int y, const std::string& line) {
  // A number's sign as the dialogue echoes it, APL's high minus: the caption's plain ASCII
  // (commands/picture.h, for every device) has a minus at the start of a number.
  std::u32string text = utf32(line);
  for (std::size_t i = 0; i + 1 < text.size(); ++i)
    if (text[i] == U'-' && (i == 0 || text[i - 1] == U' ') &&
        ((text[i + 1] >= U'0' && text[i + 1] <= U'9') || text[i + 1] == U'.'))
      text[i] = U'\u00AF';
  draw_text(layout_.caption_x, y, text);
}

void TekScreen::move_cursor(int x, int y) {
  if (cursor_ && *cursor_ == DevicePoint{x, y}) return;
  tek_.alpha_at(at(x, y));
  cursor_ = DevicePoint{x, y};
}

void TekScreen::draw_picture_and_captions() {
  if (!picture_) return;
  const bool cut = draw_picture(*picture_, tek_, unit_, layout_);
  cursor_.reset();
  int y = layout_.caption_top;
  for (const auto& line : captions_) {
    if (!line.empty()) draw_caption(y, line);
    y -= tek_screen::line_height;
  }
  if (cut) draw_caption(y, std::string(texts_cut_line));
}

void TekScreen::draw_frame() {
  if (!frame_) return;
  const double u = unit_;
  render(*frame_, Placement{u, 0, 0},
         {0, 0, u * (tek_screen::width - 1), u * (tek_screen::height - 1)}, Rendering{.point = u},
         tek_);
  tek_.style({});
  cursor_.reset();
}

void TekScreen::set_frame(std::shared_ptr<const Drawing2> frame, const TekLayout& layout) {
  frame_ = std::move(frame);
  layout_ = layout;
}

TekScreen::Parts TekScreen::replace_picture(std::shared_ptr<const Picture> picture) {
  Parts parts;
  picture_ = std::move(picture);
  captions_ = picture_->caption;
  in_document_ = false;
  cursor_.reset();
  tek_.page();
  ++pages_;
  draw_frame();
  parts.before = take();
  draw_picture_and_captions();
  parts.picture = take();
  draw_dialogue();
  parts.after = take();
  return parts;
}

void TekScreen::new_page() {
  // A page drawn anew shows the current picture alone: the ones a DISPLAY drew it over belonged
  // to the page before, and to no projection of this one.
  if (picture_) captions_ = picture_->caption;
  cursor_.reset();
  tek_.page();
  ++pages_;
  draw_frame();
  if (!in_document_) draw_picture_and_captions();
  draw_dialogue();
}

void TekScreen::draw_dialogue() {
  int row = 0;
  for (const auto& line : lines_) {
    for (const auto& r : wrap(line, flow().columns, line.set_out)) emit(row++, 0, r);
  }
  // The alpha cursor where the dialogue goes on.
  if (!open_) move_cursor(flow().x, flow().top - row * tek_screen::line_height);
}

void TekScreen::turn_page(int reserve, int carry) {
  // A new page shows the current picture alone, with its caption.
  if (picture_) captions_ = picture_->caption;
  const int columns = flow().columns;
  std::vector<Line> kept;
  int rows = 0;
  std::size_t i = lines_.size();
  if (open_ && i > 0) {
    kept.push_back(lines_.back());
    rows = static_cast<int>(wrap(lines_.back(), columns, lines_.back().set_out).size());
    --i;
  }
  int carried = 0;
  for (; i > 0; --i) {
    const int n = static_cast<int>(wrap(lines_[i - 1], columns, lines_[i - 1].set_out).size());
    if (carried + n > carry || rows + n + reserve > flow().rows) break;
    kept.insert(kept.begin(), lines_[i - 1]);
    carried += n;
    rows += n;
  }
  lines_ = std::move(kept);
  if (lines_.empty()) open_ = false;
  new_page();
}

void TekScreen::make_room(int more) {
  if (rows_of_lines() + more > flow().rows) turn_page(more, carried_rows);
}

void TekScreen::append(std::u32string_view text) {
  if (!open_) {
    make_room(1);
    lines_.emplace_back();
    lines_.back().set_out = setting_out_;
    open_ = true;
  }
  const int columns = flow().columns;
  const auto before = wrap(lines_.back(), columns, lines_.back().set_out);
  lines_.back() += text;
  const auto after = wrap(lines_.back(), columns, lines_.back().set_out);
  int first = 0;  // the row where the line being written starts
  for (std::size_t i = 0; i + 1 < lines_.size(); ++i)
    first += static_cast<int>(wrap(lines_[i], columns, lines_[i].set_out).size());
  if (first + static_cast<int>(after.size()) > flow().rows && first > 0) {
    turn_page(0, carried_rows);  // the page is full: a new one, with this line whole
    return;
  }
  // What is already on the screen must stay: every row but the last the same, the last a prefix.
  bool kept = after.size() >= before.size();
  for (std::size_t r = 0; kept && r < before.size(); ++r) {
    const bool last = r + 1 == before.size();
    kept = last ? after[r].compare(0, before[r].size(), before[r]) == 0 : after[r] == before[r];
  }
  if (!kept) {
    new_page();  // a word moved to the next row: a storage tube cannot take it back
    return;
  }
  for (std::size_t r = before.size() - 1; r < after.size(); ++r) {
    const std::size_t from = r + 1 == before.size() ? before[r].size() : 0;
    if (from < after[r].size())
      emit(first + static_cast<int>(r), static_cast<int>(from),
           std::u32string_view(after[r]).substr(from));
  }
}

std::string TekScreen::begin() {
  move_cursor(flow().x, flow().top);
  return take();
}

std::string TekScreen::text(std::string_view text, bool set_out) {
  typed_.clear();
  setting_out_ = set_out;
  const std::u32string all = utf32(text);
  std::size_t start = 0;
  while (start <= all.size()) {
    const std::size_t end = all.find(U'\n', start);
    const std::u32string_view piece(all.data() + start,
                                    (end == std::u32string::npos ? all.size() : end) - start);
    if (!piece.empty()) append(piece);
    if (end == std::u32string::npos) break;
    if (!open_) {  // an empty line
      make_room(1);
      lines_.emplace_back();
      move_cursor(flow().x, flow().top - rows_of_lines() * tek_screen::line_height);
    }
    open_ = false;
    start = end + 1;
  }
  setting_out_ = false;
  return take();
}

std::string TekScreen::type(std::string_view character) {
  const std::u32string c = utf32(character);
  append(c);
  typed_ += c;
  return take();
}

std::string TekScreen::untype() {
  if (typed_.empty() || !open_ || lines_.empty()) return {};
  typed_.pop_back();
  lines_.back().pop_back();
  new_page();  // a storage tube cannot take a character back: the page is drawn again
  return take();
}

std::string TekScreen::picture(std::shared_ptr<const Picture> picture) {
  const bool shown = picture_ && !in_document_;
  const int needed = static_cast<int>(picture->caption.size()) + (captions_.empty() ? 0 : 1);
  picture_ = std::move(picture);
  in_document_ = false;
  if (!shown || static_cast<int>(captions_.size()) + needed > layout_.caption_rows) {
    // A picture page, keeping below the picture the last rows of dialogue that fit (one row
    // stays free for what follows).
    if (!dialogue_) lines_.clear();
    open_ = open_ && !lines_.empty();
    turn_page(1, carried_rows);
    return take();
  }
  // On the page already showing a picture: drawn over it, as a storage tube does, the caption
  // below the ones in the column.
  cursor_.reset();
  captions_.emplace_back();
  int y = layout_.caption_top - static_cast<int>(captions_.size()) * tek_screen::line_height;
  draw_picture(*picture_, tek_, unit_, layout_);
  for (const auto& line : picture_->caption) {
    draw_caption(y, line);
    captions_.push_back(line);
    y -= tek_screen::line_height;
  }
  // Back to where the dialogue goes on.
  const int rows = rows_of_lines();
  if (open_) {
    const auto last = wrap(lines_.back(), flow().columns, lines_.back().set_out);
    emit(rows - 1, static_cast<int>(last.back().size()), U"");
  } else {
    move_cursor(flow().x, flow().top - rows * tek_screen::line_height);
  }
  return take();
}

std::string TekScreen::erase() {
  picture_.reset();
  captions_.clear();
  lines_.clear();
  open_ = false;
  in_document_ = false;
  new_page();
  return take();
}

std::string TekScreen::document_page(bool always) {
  if ((!picture_ && !always) || in_document_) return {};
  saved_lines_ = lines_;
  saved_open_ = open_;
  in_document_ = true;
  lines_.clear();
  open_ = false;
  new_page();
  return take();
}

std::string TekScreen::end_document() {
  if (!in_document_) return {};
  in_document_ = false;
  lines_ = std::move(saved_lines_);
  open_ = saved_open_;
  new_page();
  return take();
}

std::string TekScreen::clear() {
  lines_.clear();
  open_ = false;
  new_page();
  return take();
}

std::string TekScreen::repaint() {
  new_page();
  return take();
}

DevicePoint TekScreen::next_character() const {
  const Flow f = flow();
  const int rows = rows_of_lines();
  if (open_ && !lines_.empty()) {
    const auto last = wrap(lines_.back(), f.columns, lines_.back().set_out);
    return {f.x + static_cast<int>(last.back().size()) * tek_screen::char_width,
            f.top - (rows - 1) * tek_screen::line_height};
  }
  return {f.x, f.top - rows * tek_screen::line_height};
}

std::string TekScreen::enquire(DevicePoint& at, int aside) {
  at = next_character();
  at.x += aside;
  tek_.alpha_at(this->at(at.x, at.y));
  cursor_ = aside != 0 ? std::nullopt : std::optional<DevicePoint>(at);
  return take() + "\x1B\x05";
}

std::vector<TekScreen::Row> TekScreen::rows() const {
  std::vector<Row> out;
  if (picture_ && !in_document_) {
    int y = layout_.caption_top;
    for (const auto& line : captions_) {
      if (!line.empty()) out.push_back({layout_.caption_x, y, utf32(line)});
      y -= tek_screen::line_height;
    }
  }
  const Flow f = flow();
  int row = 0;
  for (const auto& line : lines_)
    for (const auto& r : wrap(line, f.columns, line.set_out))
      out.push_back({f.x, f.top - row++ * tek_screen::line_height, r});
  return out;
}

}  // namespace igds
