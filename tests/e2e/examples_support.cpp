#include "tests/e2e/examples_support.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "tests/support/process.h"

namespace igds::test {

namespace {

std::filesystem::path expected_dir() {
  return source_dir() / "tests" / "e2e" / "expected";
}

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// "* picture: page 3 ..." in an example's header: the Tek page its picture shows.
int picture_page_of(std::string_view text) {
  constexpr std::string_view key = "picture: page ";
  for (const auto& line : split_lines(text)) {
    auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] != '*') break;  // the header has ended
    auto at = line.find(key);
    if (at != std::string::npos) return std::atoi(line.c_str() + at + key.size());
  }
  return -1;
}

}  // namespace

std::vector<Example> examples() {
  std::vector<Example> list;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "scripts/examples")) {
    if (entry.path().extension() != ".igds") continue;
    Example e;
    e.name = entry.path().stem().string();
    e.file = entry.path();
    e.picture_page = picture_page_of(read_file(entry.path()));
    list.push_back(std::move(e));
  }
  std::sort(list.begin(), list.end(),
            [](const Example& a, const Example& b) { return a.name < b.name; });
  return list;
}

std::vector<std::string> command_lines(std::string_view file_text) {
  constexpr std::string_view lamp = "\u235D";  // ⍝, APL's comment
  std::vector<std::string> lines;
  for (auto line : split_lines(file_text)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos &&
        (line[first] == '*' || line.compare(first, lamp.size(), lamp) == 0))
      continue;
    if (auto at = line.find(lamp); at != std::string::npos) line.erase(at);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::string compare_expected(const std::string& file, const std::string& actual) {
  auto path = expected_dir() / file;
  const char* update = std::getenv("IGDS_UPDATE_GOLDEN");
  if (update && std::string_view(update) == "1") {
    std::string old = std::filesystem::exists(path) ? read_file(path) : std::string();
    if (old == actual) return "";
    std::filesystem::create_directories(path.parent_path());
    TempDir scratch;
    write_file(scratch.path() / "old", old);
    write_file(path, actual);
    auto diff = run({"diff", "-u", (scratch.path() / "old").string(), path.string()});
    int added = 0, removed = 0;
    for (const auto& line : split_lines(diff.out)) {
      if (line.rfind("+++", 0) == 0 || line.rfind("---", 0) == 0) continue;
      if (line.rfind('+', 0) == 0) ++added;
      if (line.rfind('-', 0) == 0) ++removed;
    }
    fmt::print("updated {}: {} lines added, {} removed\n", path.string(), added, removed);
    auto lines = split_lines(diff.out);
    for (std::size_t i = 0; i < lines.size() && i < 40; ++i) fmt::print("  {}\n", lines[i]);
    if (lines.size() > 40) fmt::print("  ... ({} more diff lines)\n", lines.size() - 40);
    return "";
  }
  if (!std::filesystem::exists(path))
    return fmt::format("{} is missing (make it with IGDS_UPDATE_GOLDEN=1)", path.string());
  std::string expected = read_file(path);
  if (expected == actual) return "";
  auto want = split_lines(expected), got = split_lines(actual);
  std::size_t i = 0;
  while (i < want.size() && i < got.size() && want[i] == got[i]) ++i;
  return fmt::format(
      "{} differs at line {}:\n  expected: {}\n  actual:   {}\n(IGDS_UPDATE_GOLDEN=1 "
      "rewrites it and prints the diff)",
      path.string(), i + 1, i < want.size() ? want[i] : "<end>", i < got.size() ? got[i] : "<end>");
}

std::string without_disk(std::string text, const std::filesystem::path& disk) {
  for (std::string from : {disk.string(), std::filesystem::canonical(disk).string()}) {
    if (from.empty()) continue;
    for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos;) {
      text.replace(at, from.size(), "<DISK>");
      at += 6;
    }
  }
  return text;
}

TekDrawing decode_tek(std::string_view s) {
  // The 4013's alpha cell and home position (xterm's TEKHOME for the large font).
  constexpr double cell_w = 14, cell_h = 22, home_y = 748;
  enum class Mode { alpha, graph, point };
  TekDrawing d;
  d.pages.emplace_back();
  Mode mode = Mode::alpha;
  TekPoint beam{0, home_y};
  bool first_address = true;  // the next complete address after GS is a dark move
  int hi_y = -1, lo_y = -1, hi_x = -1, extra = -1;
  bool extra_now = false;  // an Extra byte came with the address being received
  enum class Last { none, hi, lo } last = Last::none;
  bool in_text = false;

  auto error = [&](std::size_t at, std::string what) {
    if (d.errors.size() < 20) d.errors.push_back(fmt::format("byte {}: {}", at, what));
  };
  auto put_text = [&](std::string_view bytes) {
    auto& texts = d.pages.back().texts;
    if (!in_text) {
      texts.push_back({beam, ""});
      in_text = true;
    }
    texts.back().text += bytes;
  };
  auto newline = [&] {
    beam.y -= cell_h;
    if (beam.y < 0) beam.y = home_y;
    in_text = false;
  };

  for (std::size_t i = 0; i < s.size(); ++i) {
    auto c = static_cast<unsigned char>(s[i]);
    if (c == 0x1B) {  // ESC sequences
      if (i + 1 >= s.size()) {
        error(i, "ESC at the end of the stream");
        break;
      }
      auto n = static_cast<unsigned char>(s[++i]);
      if (n == 0x0C) {  // page
        d.pages.emplace_back();
        mode = Mode::alpha;
        beam = {0, home_y};
        in_text = false;
      } else if (n == '[') {  // an xterm control sequence (switching windows): skip it
        while (i + 1 < s.size() && !(s[i + 1] >= 0x40 && s[i + 1] <= 0x7E)) ++i;
        ++i;
      } else if (n == 0x03 || n == 0x05 || n == 0x17 || n == 0x0E || n == 0x0F ||
                 (n >= '8' && n <= ';') || (n >= 0x60 && n <= 0x6F)) {
        // switch back to VT, enquiry, hard copy, APL set on/off, character size, line style
      } else {
        error(i, fmt::format("unknown ESC 0x{:02X}", n));
      }
      continue;
    }
    if (c == 0x1D || c == 0x1C) {  // GS graph, FS point plot
      mode = c == 0x1D ? Mode::graph : Mode::point;
      first_address = true;
      last = Last::none;
      in_text = false;
      continue;
    }
    if (c == 0x1F) {  // US alpha at the beam
      mode = Mode::alpha;
      in_text = false;
      continue;
    }
    if (c == '\r') {
      mode = Mode::alpha;
      beam.x = 0;
      in_text = false;
      continue;
    }
    if (c == '\n') {
      mode = Mode::alpha;
      newline();
      continue;
    }
    if (c == 0x07 || c == 0x00) continue;  // bell, padding
    if (c == 0x08) {
      beam.x = std::max(0.0, beam.x - cell_w);
      in_text = false;
      continue;
    }
    if (mode == Mode::alpha) {
      if (c < 0x20) {
        error(i, fmt::format("control byte 0x{:02X} in alpha mode", c));
        continue;
      }
      if (c >= 0x80) {  // a UTF-8 sequence: one character
        std::size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
        put_text(s.substr(i, len));
        i += len - 1;
      } else {
        if (beam.x + cell_w > 1024) {
          beam.x = 0;
          newline();
        }
        put_text(s.substr(i, 1));
      }
      beam.x += cell_w;
      continue;
    }
    // Graph or point mode: address bytes (spec tek4013.md, Address bytes).
    if (c < 0x20 || c >= 0x80) {
      error(i, fmt::format("byte 0x{:02X} inside graph data", c));
      continue;
    }
    int tag = c & 0x60, value = c & 0x1F;
    if (tag == 0x20) {
      if (last == Last::lo)
        hi_x = value;
      else
        hi_y = value;
      last = Last::hi;
    } else if (tag == 0x60) {
      if (last == Last::lo) {  // two in a row: the first was the 12-bit Extra byte
        extra = lo_y;
        extra_now = true;
      }
      lo_y = value;
      last = Last::lo;
    } else {  // LoX completes the address
      if (hi_y < 0 || lo_y < 0 || hi_x < 0) {
        error(i, "an address completed before its high bytes were ever sent");
        last = Last::none;
        continue;
      }
      TekPoint p;
      if (extra_now) {
        p.x = ((hi_x << 7) | (value << 2) | (extra & 3)) / 4.0;
        p.y = ((hi_y << 7) | (lo_y << 2) | ((extra >> 2) & 3)) / 4.0;
      } else {
        p.x = (hi_x << 5) | value;
        p.y = (hi_y << 5) | lo_y;
      }
      extra_now = false;
      last = Last::none;
      if (mode == Mode::point) {
        d.pages.back().segments.push_back({p, p});
      } else if (!first_address) {
        d.pages.back().segments.push_back({beam, p});
      }
      first_address = false;
      beam = p;
    }
  }
  return d;
}

double distance(TekPoint p, const TekSegment& s) {
  double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (s.a.x + t * dx), p.y - (s.a.y + t * dy));
}

}  // namespace igds::test
