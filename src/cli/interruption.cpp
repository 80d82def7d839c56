// Ctrl-C and SIGTERM: a flag for the runs, a watchdog for everything else (interruption.hpp).
#include "interruption.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <thread>

namespace plyimpact::cli {

namespace {

std::atomic<bool> flag{false}; // NOLINT(cppcoreguidelines-avoid-non-const-global-variables): signal state
int wake[2] = {-1, -1};        // NOLINT(cppcoreguidelines-avoid-non-const-global-variables): self-pipe

/// Async-signal-safe: a flag, one byte into the self-pipe, or _exit on the second signal.
extern "C" void on_interrupt(int /*signal*/) {
  if (flag.exchange(true)) _exit(exit_interrupted);
  const char byte = 'x';
  (void)!::write(wake[1], &byte, 1);
}

void write_stderr(const char* text, std::size_t size) {
  (void)!::write(STDERR_FILENO, text, size);
}

/// Waits for the first signal, lets the run stop by itself for interruption_grace, then ends the process.
void watchdog() {
  char byte = 0;
  while (::read(wake[0], &byte, 1) < 0 && errno == EINTR) {
  }
  std::this_thread::sleep_for(interruption_grace);
  constexpr char message[] = "plyimpact: interrupted: stopped; what was written stays (docs/robustness.md, "
                             "\"Interrupting a run\")\n";
  write_stderr(message, sizeof message - 1);
  _exit(exit_interrupted);
}

} // namespace

void handle_interruptions() {
  if (::pipe2(wake, O_CLOEXEC) != 0) return; // no watchdog: the runs' flag still works
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0; // no SA_RESTART: a waiting poll or read returns EINTR and its caller stops
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
  // The watchdog blocks both signals, so that they reach a thread whose waits they should interrupt.
  sigset_t both, before;
  sigemptyset(&both);
  sigaddset(&both, SIGINT);
  sigaddset(&both, SIGTERM);
  ::pthread_sigmask(SIG_BLOCK, &both, &before);
  std::thread(watchdog).detach();
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
}

const std::atomic<bool>& interrupted() {
  return flag;
}

} // namespace plyimpact::cli
