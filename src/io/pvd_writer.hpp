#pragma once
// A ParaView collection (.pvd): the index of a time series of .vtu/.vtp files. Opening the .pvd
// in ParaView loads the whole series with its times. See docs/output-format.md.
#include <string>
#include <vector>

namespace flotsam {

class PvdWriter {
 public:
  /// When the index is first written: an empty collection at once (replacing any file there),
  /// or with its first dataset (a run's index: nothing to list before its first output).
  enum class Start { empty_now, at_first_add };
  explicit PvdWriter(std::string path, Start start = Start::empty_now);

  /// Adds a dataset at time [s]; `relative_file` is relative to the .pvd's folder. Datasets of
  /// the same time with different `part`s (say the flow as part 0, the bodies as part 1) are
  /// loaded together as the blocks of one multiblock dataset. The whole index is rewritten
  /// (through a temporary file and a rename) after each add, so an interrupted run still leaves
  /// a valid index of what it wrote.
  void add(double time, const std::string& relative_file, int part = 0);

  const std::string& path() const { return path_; }

 private:
  void write() const;

  struct Entry {
    double time;  // [s]
    std::string file;
    int part;
  };
  std::string path_;
  std::vector<Entry> entries_;
};

}  // namespace flotsam
