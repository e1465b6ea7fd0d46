#pragma once
// Two kinds of errors, two ways (spec/style.md habit 10):
//  * programming errors are assertions;
//  * bad input and runs that leave the model's validity are exceptions carrying their context
//    (file, line, key, node, body, time), caught in main, printed, and turned into exit code 1.
#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace flotsam {

/// The user's input is wrong: a file, a key, a node or a body. The message names which and says
/// what was expected.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run stopped because the solution left the model's validity (instability, a node that dried,
/// a body outside the domain). The message names the time, the place and the quantity.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <class... Args>
[[noreturn]] void throw_input_error(fmt::format_string<Args...> format, Args&&... args) {
  throw InputError(fmt::format(format, std::forward<Args>(args)...));
}

template <class... Args>
[[noreturn]] void throw_run_error(fmt::format_string<Args...> format, Args&&... args) {
  throw RunError(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace flotsam
