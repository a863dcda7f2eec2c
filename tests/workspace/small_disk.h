// A small tmpfs mounted in a test folder: a disk that really fills up, or that is read-only
// (as root, permission bits do not stop writes; a read-only mount does). Needs the right to
// mount; mounted() says whether it worked, so that tests can say why they skip.
#pragma once

#include <sys/mount.h>

#include <filesystem>
#include <string>

namespace igds::test {

class SmallDisk {
 public:
  SmallDisk(const std::filesystem::path& where, std::size_t kilobytes) : path_(where) {
    std::filesystem::create_directories(path_);
    std::string options = "size=" + std::to_string(kilobytes) + "k";
    mounted_ = ::mount("tmpfs", path_.c_str(), "tmpfs", 0, options.c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted_) ::umount2(path_.c_str(), MNT_DETACH);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;

  bool mounted() const { return mounted_; }
  const std::filesystem::path& path() const { return path_; }
  bool make_read_only() {
    return ::mount(nullptr, path_.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr) == 0;
  }

 private:
  std::filesystem::path path_;
  bool mounted_ = false;
};

}  // namespace igds::test
