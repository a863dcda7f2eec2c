// One igds per disk: BINSAVE.IGDSLOCK, held under an exclusive flock for as long as igds runs
// (docs/disk.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace igds::disk {

class DiskLock {
 public:
  // Takes the lock of the disk folder `dir` (shown as `where` in reports). Throws Report naming
  // the process that holds it when another live igds uses the disk, and when the lock cannot be
  // made (a read-only disk; something that is not a plain file of igds's at the lock's name,
  // which is left as it is). A lock left by a process that has ended is taken over; `notices`
  // gets what the user should be told.
  DiskLock(const std::filesystem::path& dir, std::vector<std::string>& notices);
  ~DiskLock();  // removes the lock file, then releases it
  DiskLock(const DiskLock&) = delete;
  DiskLock& operator=(const DiskLock&) = delete;

  // False when the process number could not be written in the lock for want of space (the
  // lock holds all the same; the disk is full).
  bool disk_had_room() const { return room_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool room_ = true;
};

}  // namespace igds::disk
