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
  return fmt::format("[{}] ", number_text(current_));
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
  std::u32string_view rest = trim(text);
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
