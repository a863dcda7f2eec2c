// The tree: each layer includes nothing of a layer above it (interp -> commands -> devices ->
// workspace; workspace/kernels and workspace/numbers -> nothing of igds), the libraries of their
// own include only what they are linked with, every source file of a layer is built, and every
// document a comment cites is in the repository.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "tests/support/process.h"

namespace igds::test {

namespace {

// The layers, lowest first, and what each may include besides itself and the layers below.
int rank(const std::string& path) {
  if (path.starts_with("workspace/kernels/") || path.starts_with("workspace/numbers/")) return 0;
  if (path.starts_with("workspace/")) return 1;
  if (path.starts_with("devices/")) return 2;
  if (path.starts_with("commands/")) return 3;
  if (path.starts_with("interp/")) return 4;
  return -1;
}

// The sources of the layers, or of `folders`.
std::vector<std::string> sources(std::initializer_list<const char*> folders = {
                                     "workspace", "devices", "commands", "interp"}) {
  std::vector<std::string> out;
  for (const char* folder : folders)
    for (const auto& e : std::filesystem::recursive_directory_iterator(source_dir() / folder)) {
      const auto ext = e.path().extension();
      if (ext == ".cpp" || ext == ".h") out.push_back(e.path().lexically_relative(source_dir()));
    }
  return out;
}

// The igds headers a file includes.
std::vector<std::string> includes_of(const std::string& file) {
  static const std::regex include(R"re(#include "([^"]+)")re");
  const std::string text = read_file(source_dir() / file);
  std::vector<std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), include), end; it != end; ++it)
    out.push_back((*it)[1]);
  return out;
}

}  // namespace

TEST_CASE("no layer includes a layer above it") {
  int checked = 0;
  for (const auto& file : sources()) {
    const int own = rank(file);
    REQUIRE(own >= 0);
    for (const std::string& target : includes_of(file)) {
      const int other = rank(target);
      if (other < 0) continue;  // generated headers
      CAPTURE(file);
      CAPTURE(target);
      CHECK(other <= own);
      ++checked;
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("the libraries of their own include only what they are linked with (CMakeLists.txt)") {
  // igds_kernels and igds_numbers nothing of igds, not even each other; igds_apl (END APL's
  // language) only those two.
  const std::map<std::string, std::vector<std::string>> alone = {
      {"workspace/kernels/", {"workspace/kernels/"}},
      {"workspace/numbers/", {"workspace/numbers/"}},
      {"interp/apl/", {"interp/apl/", "workspace/kernels/", "workspace/numbers/"}}};
  int checked = 0;
  for (const auto& file : sources()) {
    for (const auto& [folder, allowed] : alone) {
      if (!file.starts_with(folder)) continue;
      for (const std::string& target : includes_of(file)) {
        CAPTURE(file);
        CAPTURE(target);
        CHECK(std::any_of(allowed.begin(), allowed.end(),
                          [&](const std::string& f) { return target.starts_with(f); }));
        ++checked;
      }
    }
  }
  CHECK(checked > 50);
}

TEST_CASE("every source file is listed in CMakeLists.txt, and every listed file exists") {
  const std::string cmake = read_file(source_dir() / "CMakeLists.txt");
  std::set<std::string> listed;
  const std::regex entry(R"re((?:^|\s)((?:workspace|devices|commands|interp)/[\w/]+\.cpp))re");
  for (std::sregex_iterator it(cmake.begin(), cmake.end(), entry), end; it != end; ++it)
    listed.insert((*it)[1]);
  for (const auto& file : sources()) {
    if (!file.ends_with(".cpp")) continue;
    CAPTURE(file);
    CHECK(listed.count(file) == 1);
  }
  for (const auto& file : listed) {
    CAPTURE(file);
    CHECK(std::filesystem::exists(source_dir() / file));
  }
}

TEST_CASE("every document a comment cites is in the repository") {
  // A name ending in .md in a comment: a path from the top of the tree (docs/kernels.md).
  const std::regex cited(R"re(([\w./-]+\.md)\b)re");
  std::size_t citations = 0;
  for (const auto& file : sources({"workspace", "devices", "commands", "interp", "tests"})) {
    const std::string text = read_file(source_dir() / file);
    for (std::size_t at = text.find("//"); at != std::string::npos; at = text.find("//", at)) {
      const std::size_t end = std::min(text.find('\n', at), text.size());
      const std::string comment = text.substr(at, end - at);
      for (std::sregex_iterator it(comment.begin(), comment.end(), cited), stop; it != stop; ++it) {
        const std::string document = (*it)[1];
        CAPTURE(file);
        CAPTURE(document);
        CHECK(std::filesystem::is_regular_file(source_dir() / document));
        ++citations;
      }
      at = end;
    }
  }
  CHECK(citations > 100);  // the sources do cite docs/
}

}  // namespace igds::test
