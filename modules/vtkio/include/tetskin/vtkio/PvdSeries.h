// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A ParaView time series (.pvd): a list of (time, part, file). The .pvd is
// rewritten atomically after every frame, so a run stopped halfway leaves a
// valid series of the frames written so far.

#include <filesystem>
#include <string>
#include <vector>

namespace tetskin {

class PvdSeries {
 public:
  struct Entry {
    double time;
    int part;
    std::string file;  // as written: relative to the .pvd's directory
  };

  explicit PvdSeries(std::filesystem::path pvdPath);
  // Reads a .pvd (ours or ParaView's); throws Error naming the file when it
  // is not a VTK Collection or a DataSet lacks its timestep or file.
  static PvdSeries read(const std::filesystem::path& pvdPath);

  const std::filesystem::path& path() const { return path_; }
  // `file` relative to the .pvd's directory; `part` separates datasets of one
  // time step (0 control mesh, 1 surface).
  void add(double time, int part, const std::string& file);
  void write() const;
  std::size_t size() const { return entries_.size(); }
  const std::vector<Entry>& entries() const { return entries_; }
  // The entries of `part` (0: the control mesh) in time order, each file
  // given from here (the .pvd's directory joined to it) and checked to be
  // there. Throws Error naming the .pvd when the part has no entries or a
  // file is missing: for commands that read a whole run before they work.
  std::vector<Entry> framesOfPart(int part) const;

 private:
  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace tetskin
