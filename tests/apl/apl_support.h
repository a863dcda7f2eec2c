// A session with a host that records what it prints, answers input from a queue, and may own
// names, as igds's workspace will.
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interp/apl/apl_session.h"

namespace igds::apl::test {

using Lines = std::vector<std::string>;

struct TestHost : Host {
  Lines printed;
  std::deque<std::string> input;
  std::vector<std::string> prompts;
  std::map<std::string, std::optional<Value>, std::less<>> owned;  // nullopt: no value
  std::vector<std::string> checked, set_names;
  std::string refused;  // an owned name whose assignment check() refuses
  std::string saved, loaded;

  void print(std::string_view line) override { printed.emplace_back(line); }
  std::optional<std::string> read_line(std::string_view prompt) override {
    prompts.emplace_back(prompt);
    if (input.empty()) return std::nullopt;
    std::string line = input.front();
    input.pop_front();
    return line;
  }
  bool owns(std::string_view name) const override { return owned.count(name) > 0; }
  std::optional<Value> get(std::string_view name) override { return owned.find(name)->second; }
  void check(std::string_view name, const Value&) override {
    checked.emplace_back(name);
    if (name == refused) throw Error(ErrorKind::domain);
  }
  void set(std::string_view name, const Value& v) override {
    set_names.emplace_back(name);
    owned.find(name)->second = v;
  }
  std::vector<std::string> variable_names() const override {
    std::vector<std::string> names;
    for (const auto& [name, v] : owned)
      if (v) names.push_back(name);
    return names;
  }
  std::vector<std::string> save_workspace(std::string_view name) override {
    saved = name;
    return {"SAVED " + std::string(name)};
  }
  std::vector<std::string> load_workspace(std::string_view name) override {
    loaded = name;
    return {"LOADED " + std::string(name)};
  }
};

// A session and its host; calling it with a line returns what that line printed.
struct Apl {
  TestHost host;
  AplSession session{host};
  AplSession::Next next = AplSession::Next::stay;

  Lines operator()(std::string_view line) {
    host.printed.clear();
    next = session.execute(line);
    return host.printed;
  }
  // Runs several lines, returning what the last printed.
  Lines run(const std::vector<std::string>& lines) {
    Lines out;
    for (const auto& l : lines) out = (*this)(l);
    return out;
  }
};

// What one line prints in a fresh session.
inline Lines apl(std::string_view line) {
  Apl a;
  return a(line);
}

// The first line a line prints in a fresh session (a result, or an error's report).
inline std::string first(std::string_view line) {
  Lines out = apl(line);
  return out.empty() ? std::string("(nothing)") : out[0];
}

}  // namespace igds::apl::test
