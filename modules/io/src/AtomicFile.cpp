// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/io/AtomicFile.h"

#include <unistd.h>

#include <atomic>
#include <system_error>

#include "tetskin/core/Error.h"

namespace tetskin {
namespace {

// A name beside the target (same file system, so rename is atomic) that no
// other writer of this or another process picks. The extension stays last:
// some writers (VTK's PLY writer) append theirs otherwise.
std::filesystem::path temporaryNameFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path tmp = target;
  tmp.replace_filename(target.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                       std::to_string(counter++) + target.extension().string());
  return tmp;
}

void removeQuietly(const std::filesystem::path& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

void renameOnto(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code ec;
  std::filesystem::rename(from, to, ec);
  if (ec) {
    removeQuietly(from);
    throw Error(to.string(), 0, "cannot replace the file: " + ec.message());
  }
}

// Throws Error naming `target` unless `folder` is a writable folder.
void requireWritableFolder(const std::filesystem::path& target,
                           const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw Error(
        target.string(), 0,
        "cannot be written: " + folder.string() +
            (std::filesystem::exists(folder, error) ? " is not a folder" : " does not exist"));
  if (::access(folder.c_str(), W_OK) != 0)
    throw Error(target.string(), 0, "cannot be written: " + folder.string() + " is not writable");
}

// Where a target would go: the nearest folder on its path that exists, and
// the outermost one after it that does not (empty when the target's own
// folder exists).
struct Location {
  std::filesystem::path existing, outermostMissing;
};
Location locate(const std::filesystem::path& target) {
  Location location;
  location.existing = std::filesystem::absolute(target).parent_path();
  std::error_code error;
  while (!std::filesystem::exists(location.existing, error) &&
         location.existing.has_relative_path()) {
    location.outermostMissing = location.existing;
    location.existing = location.existing.parent_path();
  }
  return location;
}

// Checks the target's location and makes the folders it lacks (a command
// line's `-o results/run1/out.vtp`, as build and simulate always did);
// returns the outermost folder made, or an empty path. Checked first: the
// writers' own messages for a missing or read-only folder name the
// temporary file (or, for VTK's PNG writer, a full disk).
std::filesystem::path makeTargetFolder(const std::filesystem::path& target) {
  const Location location = locate(target);
  requireWritableFolder(target, location.existing);
  if (location.outermostMissing.empty()) return {};
  const std::filesystem::path folder = std::filesystem::absolute(target).parent_path();
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error)
    throw Error(target.string(), 0,
                "cannot be written: " + folder.string() + " cannot be made: " + error.message());
  return location.outermostMissing;
}

// Removes the folders makeTargetFolder made for `target`, from the inside
// out, as long as they are empty: a failed write leaves nothing behind.
void removeMadeFolders(const std::filesystem::path& target,
                       const std::filesystem::path& outermost) {
  if (outermost.empty()) return;
  for (std::filesystem::path f = std::filesystem::absolute(target).parent_path();;
       f = f.parent_path()) {
    std::error_code error;
    if (!std::filesystem::remove(f, error) || f == outermost) return;
  }
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporaryNameFor(target_)) {
  madeFolder_ = makeTargetFolder(target_);
  stream_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!stream_) {
    removeMadeFolders(target_, madeFolder_);
    throw Error(target_.string(), 0, "cannot open for writing");
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    stream_.close();
    removeQuietly(temporary_);
    removeMadeFolders(target_, madeFolder_);
  }
}

void AtomicFile::commit() {
  stream_.flush();
  const bool ok = static_cast<bool>(stream_);
  stream_.close();
  if (!ok || stream_.fail()) {
    removeQuietly(temporary_);
    removeMadeFolders(target_, madeFolder_);
    committed_ = true;  // nothing left to clean up
    throw Error(target_.string(), 0, "write failed (disk full?)");
  }
  renameOnto(temporary_, target_);  // (on failure the destructor clears up)
  committed_ = true;
}

std::filesystem::path outermostMissingFolder(const std::filesystem::path& target) {
  return locate(target).outermostMissing;
}

void writeTextAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write) {
  AtomicFile file(target);
  write(file.stream());
  file.commit();
}

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path madeFolder = makeTargetFolder(target);
  const std::filesystem::path tmp = temporaryNameFor(target);
  try {
    write(tmp);
    if (!std::filesystem::exists(tmp))
      throw Error(target.string(), 0, "the writer produced no file");
    renameOnto(tmp, target);
  } catch (...) {
    removeQuietly(tmp);
    removeMadeFolders(target, madeFolder);
    throw;
  }
}

void requireWritableLocation(const std::filesystem::path& target) {
  requireWritableFolder(target, locate(target).existing);
}

}  // namespace tetskin
