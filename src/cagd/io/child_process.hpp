#pragma once
/// @file
/// Another program run to its end, as a pipe: its standard input given as text, its standard
/// output and error collected, its run bounded in time and in what it may write. The benchmark's
/// peers (compare/peer_curves.hpp) are run this way: programs of their own, never linked.
///
/// The program is started with posix_spawn (no shell: `argv[0]` is a path, or a name looked up in
/// PATH), with `environment` added to this process's; its three streams are pipes, written and
/// read together by poll, so neither side blocks on a full pipe. At `seconds` or at more than
/// `max_output` bytes of output, the program is killed (SIGKILL) and the run says so. Errors of
/// this process (no pipe, no spawn) throw OutputError; everything the program does is in the run.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace cagd {

/// How a program ended (see above).
struct ProgramRun {
    bool started = false;    ///< false: it could not be started (`error` says why)
    int exit_status = -1;    ///< its exit status, when it exited (−1 otherwise)
    int signal = 0;          ///< the signal that ended it (0: it exited)
    bool timed_out = false;  ///< killed at the time limit
    bool too_much = false;   ///< killed at the output limit
    std::string output;      ///< its standard output
    std::string error;       ///< its standard error (at most the last 64 KiB), or why it did not start
    /// True when it exited with status 0, within the limits.
    bool succeeded() const { return started && exit_status == 0 && !timed_out && !too_much; }
    /// One line: "exit status 3", "killed by signal 9", "timed out after 60 s", … and its last error line.
    std::string describe() const;
};

/// The last line of `text` without its line break: a program's reason on its standard error.
std::string last_line(std::string text);

/// Runs `argv` (see above) with `input` on its standard input.
ProgramRun run_program(const std::vector<std::string>& argv, const std::string& input,
                       const std::vector<std::pair<std::string, std::string>>& environment = {}, double seconds = 600.0,
                       std::size_t max_output = std::size_t{1} << 30);

}  // namespace cagd
