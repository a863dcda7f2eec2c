#include "commands/answers.h"

#include <cmath>

#include <fmt/format.h>

#include "commands/command.h"
#include "workspace/disk/disk.h"
#include "workspace/numbers/typed.h"

namespace igds {

namespace {

enum Answer { yes, no };
constexpr Choice yes_no_words[] = {{"YES", yes}, {"NO", no}};

}  // namespace

std::optional<long long> parse_integer(std::string_view word, long long low, long long high) {
  auto value = parse_typed_number(word);
  if (!value || !std::isfinite(*value) || std::floor(*value) != *value) return std::nullopt;
  if (*value < static_cast<double>(low) || *value > static_cast<double>(high)) return std::nullopt;
  return static_cast<long long>(*value);
}

std::span<const Choice> yes_no() {
  return yes_no_words;
}

std::optional<bool> parse_yes_no(std::span<const std::string_view> words) {
  if (words.size() != 1) return std::nullopt;
  const Choice* c = choose(yes_no_words, words[0]);
  if (!c) return std::nullopt;
  return c->code == yes;
}

std::string ask_file_name(Context& ctx, const Prompt& prompt) {
  return ask_for(ctx, prompt, [](const std::vector<std::string>& words) {
    auto name = words.size() == 1 ? cms_name(words[0]) : std::nullopt;
    if (!name) throw ParameterError(name_rule);
    return *name;
  });
}

void expect_no_more_words(Context& ctx, const char* report) {
  if (ctx.has_pending()) throw Report(report);
}

std::string command_word_reason(std::string_view word, std::string_view how_to_finish) {
  if (word.size() < 2) return {};
  const Command* c = find_command(word);
  if (!c) return {};
  return fmt::format("{} IS A COMMAND: {}", c->name, how_to_finish);
}

}  // namespace igds
