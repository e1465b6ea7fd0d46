#include "mesh/gmsh_session.hpp"

#include <gmsh.h>

#include <omp.h>

#include <exception>

namespace flotsam {
namespace {

std::mutex& gmsh_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

GmshSession::GmshSession() : lock_(gmsh_mutex()), omp_threads_(omp_get_max_threads()) {
  // No command-line arguments, no user configuration files: the same input gives the same mesh.
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);      // no output on the terminal
  gmsh::option::setNumber("General.Verbosity", 1);     // log errors only
  gmsh::option::setNumber("General.AbortOnError", 2);  // errors throw (caught by callers)
  gmsh::option::setNumber("General.NumThreads", 1);    // single-threaded: deterministic meshes
  gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
}

GmshSession::~GmshSession() {
  try {
    gmsh::finalize();
  } catch (...) {  // a destructor must not throw; Gmsh's state is reset by the next initialize
  }
  omp_set_num_threads(omp_threads_);  // General.NumThreads = 1 set the whole process's count
}

std::string current_gmsh_error() {
  std::string text;
  try {
    throw;
  } catch (const std::string& message) {
    text = message;
  } catch (const std::exception& error) {
    text = error.what();
  } catch (...) {
  }
  if (text.empty()) {
    try {
      gmsh::logger::getLastError(text);
    } catch (...) {
    }
  }
  return text.empty() ? std::string("unknown Gmsh error") : text;
}

}  // namespace flotsam
