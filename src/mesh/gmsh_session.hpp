#pragma once
// RAII access to the Gmsh C++ API. Gmsh keeps one global model and one global option table, so
// at most one GmshSession exists at a time in the process: the constructor takes a process-wide
// mutex, initializes Gmsh quietly and single-threaded (for reproducible meshes), and the
// destructor finalizes Gmsh and releases the mutex. Sessions may follow one another any number
// of times; they must not nest (a nested session in the same thread would deadlock).
#include <mutex>
#include <string>

namespace flotsam {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
  int omp_threads_;  // OpenMP's thread count before the session: Gmsh sets its own, restored
};

/// Text of the exception being handled, for use inside a catch block around Gmsh calls (Gmsh
/// throws std::string or std::exception), falling back on Gmsh's last logged error.
std::string current_gmsh_error();

}  // namespace flotsam
