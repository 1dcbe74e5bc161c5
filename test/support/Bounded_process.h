// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TEST_BOUNDED_PROCESS_H
#define EXPMAP_TEST_BOUNDED_PROCESS_H

// Running a program under a wall-clock and a memory limit, for tests that
// feed hostile input to the `expmap` program: a hang or a runaway
// allocation must show up as a failed test, not as a stuck or killed
// machine.

#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace expmap_test {

struct Process_result {
  bool exited = false;     // ended by exit(), not by a signal or the time limit
  bool timed_out = false;  // killed at the wall-clock limit
  int status = -1;         // exit status if `exited`
  int signal = 0;          // the signal that ended it otherwise
};

/// Runs `program` with `args`, stdout and stderr to the given files, with at
/// most `address_space_bytes` of virtual memory (an allocation beyond it
/// fails inside the program, which must report it) and `wall_seconds` of
/// time (then it is killed).
inline Process_result run_bounded(const std::string& program, const std::vector<std::string>& args,
                                  const std::string& stdout_path, const std::string& stderr_path,
                                  double wall_seconds, unsigned long long address_space_bytes) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  const pid_t pid = ::fork();
  if (pid == 0) {
    rlimit memory{address_space_bytes, address_space_bytes};
    ::setrlimit(RLIMIT_AS, &memory);
    const int out = ::open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) ::_exit(127);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  Process_result result;
  if (pid < 0) return result;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(wall_seconds);
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      result.timed_out = true;
      return result;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFEXITED(status)) {
    result.exited = true;
    result.status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
  return result;
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_BOUNDED_PROCESS_H
