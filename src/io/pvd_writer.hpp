#pragma once
// A ParaView collection (.pvd): the index of a time series of .vtu/.vtp files. Opening the .pvd
// in ParaView loads the whole series with its times. See docs/output-format.md.
#include <string>
#include <vector>

namespace flotsam {

class PvdWriter {
 public:
  /// When the index is written: an empty collection at once (replacing any file there), then
  /// after each add; or from its first dataset on, after each add (a run's index: nothing to list
  /// before its first output); or once, when closed (a run that is rerun whole when interrupted,
  /// an ensemble's member: one file written, none replaced).
  enum class Start { empty_now, at_first_add, when_closed };
  explicit PvdWriter(std::string path, Start start = Start::empty_now);
  /// A `when_closed` index not yet written is written (errors swallowed: close() reports them).
  ~PvdWriter();
  PvdWriter(const PvdWriter&) = delete;
  PvdWriter& operator=(const PvdWriter&) = delete;

  /// Adds a dataset at time [s]; `relative_file` is relative to the .pvd's folder. Datasets of
  /// the same time with different `part`s (say the flow as part 0, the bodies as part 1) are
  /// loaded together as the blocks of one multiblock dataset. The whole index is rewritten
  /// (through a temporary file and a rename) after each add, so an interrupted run still leaves
  /// a valid index of what it wrote; a `when_closed` index waits for close().
  void add(double time, const std::string& relative_file, int part = 0);
  /// Writes a `when_closed` index listing every dataset added, if any (as `at_first_add`, no
  /// file lists nothing); once: later calls do nothing, a later add() is an error. The other
  /// indexes are already up to date.
  void close();

  const std::string& path() const { return path_; }

 private:
  void write() const;

  struct Entry {
    double time;  // [s]
    std::string file;
    int part;
  };
  std::string path_;
  Start start_;
  bool closed_ = false;
  std::vector<Entry> entries_;
};

}  // namespace flotsam
