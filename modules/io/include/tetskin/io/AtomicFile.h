// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// All-or-nothing file output: data goes to a temporary file beside the target,
// which replaces the target only once everything was written. A failed or
// interrupted run therefore never leaves a half-written output. Folders the
// target's path lacks are made first (and removed again when the write
// fails); a file in the way, or a folder that is not writable, is an error
// naming the target.

#include <filesystem>
#include <fstream>
#include <functional>

namespace tetskin {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  std::ostream& stream() { return stream_; }
  const std::filesystem::path& temporaryPath() const { return temporary_; }
  const std::filesystem::path& target() const { return target_; }

  // Flushes, checks for write errors and renames onto the target. Throws Error.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::filesystem::path madeFolder_;  // the outermost folder made for the target
  std::ofstream stream_;
  bool committed_ = false;
};

// Writes through `write(stream)` atomically.
void writeTextAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write);

// For writers that insist on a file name of their own (VTK's): `write(tmp)`
// must create the file `tmp`, which then replaces the target.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& write);

// The outermost folder on `target`'s path that does not exist yet (which
// writing it would make), or an empty path when its folder exists: for
// commands writing several files that remove what they made on failure.
std::filesystem::path outermostMissingFolder(const std::filesystem::path& target);

// Throws Error naming `target` when no file could be written there because
// the nearest existing folder on its path is a file, or is not writable (the
// folders after it would be made). For commands that work long before they
// write, so that they fail before the work rather than after it.
void requireWritableLocation(const std::filesystem::path& target);

}  // namespace tetskin
