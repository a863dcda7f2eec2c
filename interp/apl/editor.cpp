#include "interp/apl/editor.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "interp/apl/error.h"
#include "interp/apl/function.h"
#include "interp/apl/text.h"

namespace igds::apl {

namespace {

std::u32string_view trim(std::u32string_view s) {
  while (!s.empty() && (s.front() == U' ' || s.front() == U'\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == U' ' || s.back() == U'\t')) s.remove_suffix(1);
  return s;
}

// A line number as typed: digits with at most four decimals; with the step of its last
// decimal place (1 for an integer, 0.1 for 2.5, ...).
std::optional<std::pair<std::int64_t, std::int64_t>> parse_number(std::u32string_view s) {
  s = trim(s);
  if (s.empty()) return std::nullopt;
  std::int64_t whole = 0, fraction = 0, step = 10000;
  std::size_t i = 0;
  for (; i < s.size() && s[i] >= U'0' && s[i] <= U'9'; ++i) {
    whole = whole * 10 + (s[i] - U'0');
    if (whole > 1000000) return std::nullopt;
  }
  if (i == 0 && (i >= s.size() || s[i] != U'.')) return std::nullopt;
  if (i < s.size() && s[i] == U'.') {
    ++i;
    std::int64_t scale = 1000;
    for (; i < s.size() && s[i] >= U'0' && s[i] <= U'9'; ++i) {
      if (scale == 0) return std::nullopt;
      fraction += (s[i] - U'0') * scale;
      step = scale;
      scale /= 10;
    }
  }
  if (i != s.size()) return std::nullopt;
  return std::pair{whole * 10000 + fraction, step};
}

// The position of a closing ∇ at the end of the line, outside quotes, or npos.
std::size_t closing_del(std::u32string_view s) {
  s = trim(s);
  if (s.empty() || s.back() != U'∇') return std::u32string_view::npos;
  std::size_t quotes = static_cast<std::size_t>(std::count(s.begin(), s.end() - 1, U'\''));
  return quotes % 2 == 0 ? s.size() - 1 : std::u32string_view::npos;
}

}  // namespace

Editor::Editor(const std::vector<std::string>& source) {
  header_ = source.empty() ? std::string() : source[0];
  for (std::size_t i = 1; i < source.size(); ++i)
    lines_.emplace_back(static_cast<Number>(i) * unit, source[i]);
  current_ = static_cast<Number>(lines_.size() + 1) * unit;
}

std::string Editor::number_text(Number n) {
  std::string s = fmt::format("{}", n / unit);
  if (n % unit != 0) {
    std::string f = fmt::format("{:04}", n % unit);
    f.erase(f.find_last_not_of('0') + 1);
    s += fmt::format(".{}", f);
  }
  return s;
}

std::string Editor::prompt() const {
  if (mode_ != Mode::lines) return std::string(column_, ' ');
  return fmt::format("[{}] ", number_text(current_));
}

const std::string* Editor::text_of(Number n) const {
  if (n == 0) return &header_;
  for (const auto& [m, text] : lines_)
    if (m == n) return &text;
  return nullptr;
}

Editor::Step Editor::start_editing(Number n, std::size_t position) {
  const std::string* text = text_of(n);
  if (!text) throw Error(ErrorKind::defn);
  Step step;
  const std::string prefix = fmt::format("[{}] ", number_text(n));
  step.output.push_back(prefix + *text);
  edited_ = n;
  shown_ = decode_utf8(prefix + *text);
  prefix_ = decode_utf8(prefix).size();
  column_ = position > 0 ? position - 1 : 0;
  mode_ = Mode::marks;
  return step;
}

Editor::Step Editor::marks(std::u32string_view typed) {
  // Each mark applies to the character shown above it; marks under the line number do nothing.
  std::u32string revised;
  std::size_t first_insert = std::u32string::npos;
  for (std::size_t c = prefix_; c < std::max(shown_.size(), column_ + typed.size()); ++c) {
    const char32_t mark = c >= column_ && c - column_ < typed.size() ? typed[c - column_] : U' ';
    const char32_t above = c < shown_.size() ? shown_[c] : U' ';
    std::size_t blanks = 0;
    if (mark >= U'1' && mark <= U'9') blanks = mark - U'0';
    if (mark >= U'A' && mark <= U'Z') blanks = 5 * (mark - U'A' + 1);
    if (mark >= U'a' && mark <= U'z') blanks = 5 * (mark - U'a' + 1);
    if (blanks > 0 && first_insert == std::u32string::npos) first_insert = revised.size();
    revised.append(blanks, U' ');
    if (mark != U'/' && c < shown_.size()) revised.push_back(above);
  }
  while (!revised.empty() && revised.back() == U' ' &&
         (first_insert == std::u32string::npos || revised.size() > first_insert))
    revised.pop_back();
  Step step;
  shown_ = shown_.substr(0, prefix_) + revised;
  step.output.push_back(encode_utf8(shown_));
  column_ = prefix_ + (first_insert == std::u32string::npos ? revised.size() : first_insert);
  mode_ = Mode::overlay;
  return step;
}

Editor::Step Editor::overlay(std::u32string_view typed) {
  std::u32string line = shown_;
  for (std::size_t i = 0; i < typed.size(); ++i) {
    const std::size_t c = column_ + i;
    if (c >= line.size()) line.resize(c + 1, U' ');
    if (typed[i] != U' ') line[c] = typed[i];
  }
  std::u32string_view text = trim(std::u32string_view(line).substr(prefix_));
  mode_ = Mode::lines;
  column_ = 0;
  Step step;
  try {
    set_line(edited_, encode_utf8(text));
    current_ = edited_ == 0 ? unit : edited_ + step_;
  } catch (const Error& e) {
    step.output.push_back(e.what());
  }
  return step;
}

std::vector<std::string> Editor::source() const {
  std::vector<std::string> s{header_};
  for (const auto& [n, text] : lines_) s.push_back(text);
  return s;
}

std::vector<std::string> Editor::list(Number from, Number to) const {
  std::vector<std::string> out;
  if (from == 0) out.push_back("    ∇" + header_);
  for (const auto& [n, text] : lines_)
    if (n >= from && n <= to) out.push_back(fmt::format("[{}]  {}", number_text(n), text));
  if (lines_.empty() || to >= lines_.back().first) out.push_back("    ∇");
  return out;
}

void Editor::set_line(Number n, std::string text) {
  if (n == 0) {
    parse_header(text);  // DEFN ERROR for a bad header: the old one stays
    header_ = std::move(text);
    return;
  }
  auto at = std::lower_bound(lines_.begin(), lines_.end(), n,
                             [](const auto& line, Number m) { return line.first < m; });
  if (at != lines_.end() && at->first == n) {
    at->second = std::move(text);
  } else {
    lines_.insert(at, {n, std::move(text)});
  }
}

Editor::Step Editor::line(std::string_view typed) {
  Step step;
  std::u32string text = decode_utf8(typed);
  if (mode_ == Mode::marks) return marks(text);
  if (mode_ == Mode::overlay) {
    std::u32string_view laid = text;
    const std::size_t del = closing_del(laid);
    if (del != std::u32string_view::npos) laid = laid.substr(0, laid.find_last_of(U'∇'));
    step = overlay(laid);
    step.close = del != std::u32string_view::npos && step.output.empty();
    return step;
  }
  std::u32string_view rest = trim(text);
  if (!rest.empty() && rest.front() == U'∇') {
    step.close = true;
    step.reopen = rest.size() > 1;
    return step;
  }
  const std::size_t del = closing_del(rest);
  if (del != std::u32string_view::npos) {
    step.close = true;
    rest = trim(rest.substr(0, del));
  }
  const Number was = current_, was_step = step_;
  try {
    while (!rest.empty() && rest.front() == U'[') {
      const std::size_t close = rest.find(U']');
      if (close == std::u32string_view::npos) throw Error(ErrorKind::defn);
      std::u32string_view inside = trim(rest.substr(1, close - 1));
      rest = trim(rest.substr(close + 1));
      if (inside == U"⎕") {
        auto l = list(0, INT64_MAX);
        step.output.insert(step.output.end(), l.begin(), l.end());
      } else if (!inside.empty() && inside.front() == U'⎕') {
        auto n = parse_number(inside.substr(1));
        if (!n) throw Error(ErrorKind::defn);
        auto l = list(n->first, INT64_MAX);
        step.output.insert(step.output.end(), l.begin(), l.end());
      } else if (const std::size_t q = inside.find(U'⎕');
                 q != std::u32string_view::npos && q > 0 && q + 1 < inside.size()) {
        auto n = parse_number(inside.substr(0, q));
        auto m = parse_number(inside.substr(q + 1));
        if (!n || !m || m->first % unit != 0 || !rest.empty() || step.close)
          throw Error(ErrorKind::defn);
        Step edit = start_editing(n->first, static_cast<std::size_t>(m->first / unit));
        step.output.insert(step.output.end(), edit.output.begin(), edit.output.end());
        return step;
      } else if (!inside.empty() && inside.back() == U'⎕') {
        auto n = parse_number(inside.substr(0, inside.size() - 1));
        if (!n) throw Error(ErrorKind::defn);
        auto l = list(n->first, n->first);
        if (n->first != 0 && !l.empty() && l.back() == "    ∇") l.pop_back();
        step.output.insert(step.output.end(), l.begin(), l.end());
        current_ = n->first;
        step_ = n->second;
      } else if (!inside.empty() && inside.front() == U'∆') {
        auto n = parse_number(inside.substr(1));
        if (!n || n->first == 0) throw Error(ErrorKind::defn);
        std::erase_if(lines_, [&](const auto& line) { return line.first == n->first; });
      } else {
        auto n = parse_number(inside);
        if (!n) throw Error(ErrorKind::defn);
        current_ = n->first;
        step_ = n->second;
      }
    }
    if (!rest.empty()) {
      set_line(current_, encode_utf8(rest));
      if (current_ == 0) {  // after the header comes line 1
        current_ = unit;
        step_ = unit;
      } else {
        current_ += step_;
      }
    }
  } catch (const Error& e) {  // a bad command or header changes nothing
    step.output.push_back(e.what());
    step.close = false;
    current_ = was;
    step_ = was_step;
  }
  return step;
}

}  // namespace igds::apl
