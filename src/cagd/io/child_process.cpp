#include "cagd/io/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "cagd/io/output_file.hpp"

extern char** environ;

namespace cagd {

namespace {

constexpr std::size_t kErrorTail = 64 * 1024;  // the standard error kept: its last lines say why

// A pipe whose ends close with it.
struct Pipe {
    int end[2] = {-1, -1};
    Pipe() {
        if (::pipe2(end, O_CLOEXEC) != 0)
            throw OutputError(std::string("cagd::run_program: pipe: ") + std::strerror(errno));
    }
    ~Pipe() {
        for (int& e : end) close_end(e);
    }
    static void close_end(int& e) {
        if (e >= 0) ::close(e);
        e = -1;
    }
};

}  // namespace

std::string last_line(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    const std::size_t line = text.rfind('\n');
    return line == std::string::npos ? text : text.substr(line + 1);
}

std::string ProgramRun::describe() const {
    const std::string what = !started      ? "could not be started"
                             : timed_out   ? "timed out"
                             : too_much    ? "wrote more than its output limit"
                             : signal != 0 ? "killed by signal " + std::to_string(signal)
                                           : "exit status " + std::to_string(exit_status);
    const std::string last = last_line(error);
    return last.empty() ? what : what + ": " + last;
}

ProgramRun run_program(const std::vector<std::string>& argv, const std::string& input,
                       const std::vector<std::pair<std::string, std::string>>& environment, double seconds,
                       std::size_t max_output) {
    ProgramRun run;
    if (argv.empty()) {
        run.error = "no program";
        return run;
    }
    Pipe in, out, err;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in.end[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out.end[1], 1);
    posix_spawn_file_actions_adddup2(&actions, err.end[1], 2);
    std::vector<std::string> env_text;
    for (char** e = environ; *e; ++e) {
        bool replaced = false;
        for (const auto& [name, value] : environment)
            replaced = replaced || std::strncmp(*e, (name + "=").c_str(), name.size() + 1) == 0;
        if (!replaced) env_text.emplace_back(*e);
    }
    for (const auto& [name, value] : environment) env_text.push_back(name + "=" + value);
    std::vector<char*> args, envs;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    for (std::string& e : env_text) envs.push_back(e.data());
    args.push_back(nullptr), envs.push_back(nullptr);
    // SIGPIPE is blocked in this thread while it writes to the program (a program that stops
    // reading is an EPIPE here, not the end of this process); the program starts with the mask
    // this thread had.
    sigset_t pipe_signal, old_mask;
    sigemptyset(&pipe_signal);
    sigaddset(&pipe_signal, SIGPIPE);
    ::pthread_sigmask(SIG_BLOCK, &pipe_signal, &old_mask);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setsigmask(&attributes, &old_mask);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
    pid_t pid = 0;
    const int spawned = ::posix_spawnp(&pid, argv[0].c_str(), &actions, &attributes, args.data(), envs.data());
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    bool broken_pipe = false;
    const auto restore_mask = [&] {
        if (broken_pipe) {  // the SIGPIPE of our EPIPE, pending in this thread: taken, not delivered
            const timespec now{0, 0};
            while (::sigtimedwait(&pipe_signal, nullptr, &now) < 0 && errno == EINTR) {}
        }
        ::pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
    };
    if (spawned != 0) {
        restore_mask();
        run.error = argv[0] + ": " + std::strerror(spawned);
        return run;
    }
    run.started = true;
    Pipe::close_end(in.end[0]), Pipe::close_end(out.end[1]), Pipe::close_end(err.end[1]);
    for (int fd : {in.end[1], out.end[0], err.end[0]}) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    if (input.empty()) Pipe::close_end(in.end[1]);

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    std::size_t written = 0;
    char buffer[65536];
    while (out.end[0] >= 0 || err.end[0] >= 0) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            run.timed_out = true;
            break;
        }
        pollfd fds[3] = {{in.end[1], POLLOUT, 0}, {out.end[0], POLLIN, 0}, {err.end[0], POLLIN, 0}};
        if (::poll(fds, 3, static_cast<int>(std::min<long long>(left.count(), 1000))) < 0) {
            if (errno == EINTR) continue;
            break;
        }
        if (fds[0].revents & (POLLOUT | POLLERR | POLLHUP)) {
            const ssize_t n =
                ::write(in.end[1], input.data() + written, std::min<std::size_t>(input.size() - written, 65536));
            if (n > 0) written += static_cast<std::size_t>(n);
            if (n < 0 && errno != EAGAIN && errno != EINTR) {  // it stopped reading
                broken_pipe = broken_pipe || errno == EPIPE;
                written = input.size();
            }
            if (written == input.size()) Pipe::close_end(in.end[1]);
        }
        for (int k : {1, 2}) {
            if (!(fds[k].revents & (POLLIN | POLLERR | POLLHUP))) continue;
            int& fd = k == 1 ? out.end[0] : err.end[0];
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
                Pipe::close_end(fd);
            } else if (n > 0 && k == 1) {
                run.output.append(buffer, static_cast<std::size_t>(n));
            } else if (n > 0) {
                run.error.append(buffer, static_cast<std::size_t>(n));
                if (run.error.size() > 2 * kErrorTail) run.error.erase(0, run.error.size() - kErrorTail);
            }
        }
        if (run.output.size() > max_output) {
            run.too_much = true;
            break;
        }
    }
    restore_mask();
    if (run.timed_out || run.too_much) ::kill(pid, SIGKILL);
    // Its streams are closed; it may still run (a child of its own holding none of them): waited
    // for until the deadline, then killed.
    int status = 0;
    for (;;) {
        const pid_t ended = ::waitpid(pid, &status, WNOHANG);
        if (ended == pid || (ended < 0 && errno != EINTR)) break;
        if (ended == 0 && std::chrono::steady_clock::now() >= deadline && !run.timed_out) {
            run.timed_out = true;
            ::kill(pid, SIGKILL);
        }
        if (ended == 0) ::usleep(1000);
    }
    if (WIFEXITED(status)) run.exit_status = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
    return run;
}

}  // namespace cagd
