#pragma once
// What the `cagd` process sets up before it parses its arguments (main.cpp calls it first).
namespace cagd::cli {

/// Holds closed standard descriptors, pins Eigen's product blocking (the same bits on every
/// machine: numeric/dense_blocking.hpp), keeps freed memory for reuse, and installs the signal
/// handlers that remove temporary output files.
void prepare_command_process();

}  // namespace cagd::cli
