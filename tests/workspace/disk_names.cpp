// CMS names (docs/disk.md): what is a name, and that nothing else reaches the disk.
#include <doctest/doctest.h>

#include <filesystem>

#include "tests/support/process.h"
#include "tests/workspace/disk_fixtures.h"
#include "workspace/disk/disk.h"
#include "workspace/error.h"

using namespace igds;
namespace fs = std::filesystem;

TEST_CASE("cms_name accepts 1 to 8 of letters, digits and $ # @ + - _, in capitals") {
  CHECK(cms_name("hull") == "HULL");
  CHECK(cms_name("A") == "A");
  CHECK(cms_name("12345678") == "12345678");
  CHECK(cms_name("$#@+-_ab") == "$#@+-_AB");
  CHECK(cms_name("HuLl_2") == "HULL_2");
}

TEST_CASE("cms_name refuses everything else") {
  for (std::string_view bad :
       {"", "TOOLONGNAME", "123456789", "../X", "/tmp/X", "A.B", "A B", "A/B", ".", "..",
        "\xc3\xa9", "CAF\xc3\xa9", "A\tB", "A*", "A?", "~", "A\\B", "A:B", "-\n"})
    CHECK_MESSAGE(!cms_name(bad), bad);
  CHECK(!cms_name(std::string_view("A\0B", 3)));
}

TEST_CASE("hostile names never reach the file system") {
  test::TempDir dir;
  Disk disk(dir.path());
  Workspace ws = test::make_workspace(2, 2, 1, 1);
  for (std::string_view bad : {"../X", "/tmp/X", "A.B", "TOOLONGNAME", "", "\xc3\xa9", "hull"}) {
    CAPTURE(bad);
    // Lower case is not an error for the commands (they pass cms_name's capitals), but these
    // functions take only names already in capitals.
    CHECK_THROWS_WITH_AS(save_surface(disk, bad, ws), reports::incorrect_parameter, Report);
    CHECK_THROWS_WITH_AS(restore_surface(disk, bad, ws), reports::incorrect_parameter, Report);
    CHECK_THROWS_WITH_AS(store_image(disk, bad, *ws.image), reports::incorrect_parameter, Report);
    CHECK_THROWS_WITH_AS(load_image(disk, bad), reports::incorrect_parameter, Report);
    CHECK_THROWS_WITH_AS(write_char(disk, bad, ws), reports::incorrect_parameter, Report);
  }
  CHECK(fs::is_empty(dir.path()));
  CHECK(!fs::exists(dir.path().parent_path() / "X.IGDSDATA"));
  CHECK(!fs::exists("/tmp/X.IGDSDATA"));
}

TEST_CASE("a disk is a folder that exists") {
  test::TempDir dir;
  CHECK_THROWS_WITH_AS(Disk(dir.path() / "none"),
                       ("DISK " + (dir.path() / "none").string() + " NOT FOUND").c_str(), Report);
  test::write_file(dir.path() / "file", "x");
  CHECK_THROWS_WITH_AS(Disk(dir.path() / "file"),
                       ("DISK " + (dir.path() / "file").string() + " IS NOT A FOLDER").c_str(),
                       Report);
  Disk disk(dir.path() / "");
  CHECK(disk.dir() == dir.path());
  CHECK(disk.path("HULL", "IGDSDATA") == dir.path() / "HULL.IGDSDATA");
  CHECK(!disk.exists("HULL", "IGDSDATA"));
}
