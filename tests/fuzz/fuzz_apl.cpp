// libFuzzer target for END APL: the input's lines typed into a fresh session, one after the
// other; the lines left over answer ⎕ and ⍞. Small limits (elements, work, depth) keep every
// line short, so that a crash, a hang or a leak is the session's fault, not the input's size.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>

#include "interp/apl/apl_session.h"

#include "tests/fuzz/fuzz.h"

namespace {

using igds::apl::Value;

// A host that owns one name (as igds's workspace owns INPPN) and refuses characters for it.
struct FuzzHost : igds::apl::Host {
  std::deque<std::string>* lines = nullptr;
  std::optional<Value> inppn = Value::vector({1, 2, 3, 4});

  void print(std::string_view) override {}
  std::optional<std::string> read_line(std::string_view) override {
    if (lines->empty()) return std::nullopt;
    std::string line = std::move(lines->front());
    lines->pop_front();
    return line;
  }
  bool owns(std::string_view name) const override { return name == "INPPN"; }
  std::optional<Value> get(std::string_view) override { return inppn; }
  void check(std::string_view, const Value& v) override {
    if (v.is_character()) throw igds::apl::Error(igds::apl::ErrorKind::domain);
  }
  void set(std::string_view, const Value& v) override { inppn = v; }
  std::vector<std::string> variable_names() const override { return {"INPPN"}; }
};

}  // namespace

namespace igds::fuzz {

int apl(const std::uint8_t* data, std::size_t size) {
  std::deque<std::string> lines;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    lines.emplace_back(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
  }
  FuzzHost host;
  host.lines = &lines;
  igds::apl::AplSession session(host);
  igds::apl::Limits limits;
  limits.max_elements = 1 << 16;
  limits.max_work = 500'000;
  limits.max_depth = 100;
  session.set_limits(limits);
  session.define_native("TWICE", 1, [](const Value*, const Value* right) -> std::optional<Value> {
    Value v = *right;
    for (auto& x : v.mutable_numbers()) x *= 2;
    return v;
  });
  for (int count = 0; count < 64 && !lines.empty(); ++count) {
    std::string line = std::move(lines.front());
    lines.pop_front();
    if (session.execute(line) == igds::apl::AplSession::Next::off) break;
  }
  return 0;
}

}  // namespace igds::fuzz

IGDS_FUZZ_ENTRY(apl)
