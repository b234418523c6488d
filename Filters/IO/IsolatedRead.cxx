// The child processes of IsolatedRead.h: fork, the child's limits, a pipe for
// what it read, and the parent's watch (the child's end, or a stall).
#include "IsolatedRead.h"

#include "MemoryGuard.h" // core: AvailableMemory
#include "PointCloudParsing.h"
#include "VtkMessageCapture.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <utility>

#if defined(__unix__) || defined(__APPLE__)
#define FLOWRECON_CHILD_READ
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif
#ifdef __GNUC__
// Under sanitizers (fuzzing) a crash calls libFuzzer back, which saves the input
// as a crash; a child's crash is the caller's to report.
extern "C" void __sanitizer_set_death_callback(void (*)(void)) __attribute__((weak));
#endif
#endif

namespace flowrecon
{
namespace reader
{
namespace
{

// How a read ended: 'R' its bytes, 'E' a ReadError's message, 'M' an allocation
// failure (VTK's message or ""); from the watch also 'F' the child's failure,
// 'D' the child read and goes on, 'X' the child exited (Status) before that.
struct Outcome
{
  char Kind = 0;
  std::string Text;
  int Status = 0;
};

Outcome Run(const std::string& file, const std::function<std::string()>& read)
{
  try
  {
    return { 'R', read() };
  }
  catch (const ReadError& e)
  {
    return { 'E', e.what() };
  }
  catch (const VtkAllocationFailure& e)
  {
    return { 'M', e.what() };
  }
  catch (const std::bad_alloc&)
  {
    return { 'M', "" };
  }
  catch (const std::exception& e)
  {
    return { 'E', file + ": " + e.what() };
  }
}

std::string Result(const std::string& file, const char* kind, Outcome outcome)
{
  if (outcome.Kind == 'M')
  {
    throw ReadError(
      file + ": out of memory" + (outcome.Text.empty() ? "" : " (" + OneLine(outcome.Text) + ")"));
  }
  if (outcome.Kind == 'E')
  {
    throw ReadError(outcome.Text);
  }
  if (outcome.Kind != 'R')
  {
    Fail(file, 0, std::string("cannot read ") + kind + " file (" + outcome.Text + ")");
  }
  return std::move(outcome.Text);
}

#ifdef FLOWRECON_CHILD_READ

bool InProcess()
{
  const char* value = std::getenv("FLOWRECON_READ_IN_PROCESS");
  return value && *value && std::strcmp(value, "0") != 0;
}

void WriteAll(int fd, const std::string& bytes)
{
  for (std::size_t done = 0; done < bytes.size();)
  {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0 && errno != EINTR)
    {
      return; // the parent is gone
    }
    done += n > 0 ? static_cast<std::size_t>(n) : 0;
  }
}

// The bytes a reader of `file` takes in: the file and, for a composite or
// parallel XML file, the files it names (file="..." or Source="...").
double InputBytes(const std::string& file)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const auto size = fs::file_size(file, error);
  double bytes = error ? 0.0 : static_cast<double>(size);
  const std::string extension = Lower(fs::path(file).extension().string());
  if (error ||
    (extension != ".vtm" && extension != ".vthb" && extension.compare(0, 4, ".pvt") != 0))
  {
    return bytes;
  }
  std::string text(static_cast<std::size_t>(std::min<std::uintmax_t>(size, 1 << 24)), '\0');
  std::ifstream(file, std::ios::binary).read(&text[0], static_cast<std::streamsize>(text.size()));
  for (const std::string key : { "file", "Source" })
  {
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1))
    {
      const std::size_t equals = text.find_first_not_of(" \t\r\n", at + key.size());
      const std::size_t quote = text.find_first_not_of(" \t\r\n", equals + 1);
      if (equals < text.size() && text[equals] == '=' && quote < text.size() &&
        (text[quote] == '"' || text[quote] == '\''))
      {
        const std::size_t end = std::min(text.find(text[quote], quote + 1), text.size());
        const auto named = fs::file_size(
          fs::path(file).parent_path() / text.substr(quote + 1, end - quote - 1), error);
        bytes += error ? 0.0 : static_cast<double>(named);
      }
    }
  }
  return bytes;
}

// What a child may take. Memory: what this process could still allocate, and
// at most 1 GB plus 1100 times the input (zlib, the strongest compressor VTK's
// XML writers use for point data, expands at most 1032 times): a count VTK
// believes makes it allocate and fill that much. Time without input or output:
// 10 s plus 1 s per 100 MB of input.
struct Limits
{
  double Memory;
  double Stall;
};

Limits LimitsOf(const std::string& file)
{
  const double input = InputBytes(file);
  return { std::min(AvailableMemory(), 1e9 + 1100 * input), 10 + input / 1e8 };
}

// The child ends with the caller, reports no crash to a fuzzer, prints nothing
// (a C library's crash report: the caller reports in one line) and may grow
// its address space by `memory`. Returns the limit and stderr to restore.
std::pair<rlimit, int> EnterChild(double memory)
{
#ifdef __linux__
  prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
#ifdef __GNUC__
  if (__sanitizer_set_death_callback)
  {
    __sanitizer_set_death_callback(nullptr);
  }
#endif
  const int stderrCopy = dup(2);
  const int null = open("/dev/null", O_WRONLY);
  dup2(null, 2);
  close(null);
  rlimit limit{};
  getrlimit(RLIMIT_AS, &limit);
  const rlimit saved = limit;
  long long pages = 0;
  std::ifstream("/proc/self/statm") >> pages; // the address space in use
  const double cap =
    static_cast<double>(pages) * static_cast<double>(sysconf(_SC_PAGESIZE)) + memory;
  if (pages > 0 && std::isfinite(memory) && cap < static_cast<double>(limit.rlim_cur))
  {
    limit.rlim_cur = static_cast<rlim_t>(cap);
    setrlimit(RLIMIT_AS, &limit);
  }
  return { saved, stderrCopy };
}

int Reap(pid_t pid)
{
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  return status;
}

// Bytes the child has read and written (Linux), -1 where unknown.
long long Activity(pid_t pid)
{
  std::ifstream in("/proc/" + std::to_string(pid) + "/io");
  std::string key;
  long long value = 0, sum = -1;
  while (in >> key >> value)
  {
    sum = key == "rchar:" || key == "wchar:" ? std::max(sum, 0LL) + value : sum;
  }
  return sum;
}

// Reads what the child sends on `fd` (a kind, then its text) until it ends or,
// `goesOn`, sends 'D'; stops a child that neither reads nor writes for `stall`
// seconds (VTK 9.2's legacy reader loops forever on 256 blanks).
Outcome Watch(pid_t pid, int fd, double stall, bool goesOn)
{
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  long long seen = -2;
  const double room = AvailableMemory();
  std::string in;
  for (;;)
  {
    pollfd ready{ fd, POLLIN, 0 };
    const int polled = poll(&ready, 1, 1000);
    char buffer[1 << 16];
    const ssize_t n = polled > 0 ? read(fd, buffer, sizeof(buffer)) : -1;
    if (n == 0)
    {
      break; // the child has ended
    }
    if (n > 0)
    {
      in.append(buffer, static_cast<std::size_t>(n));
      if (goesOn && in == "D")
      {
        return { 'D' };
      }
      if (in.size() <= room)
      {
        continue;
      }
    }
    const long long activity = Activity(pid);
    if (n < 0 && activity != seen)
    {
      seen = activity;
      last = Clock::now();
    }
    else if (n > 0 ||
      (activity >= 0 && std::chrono::duration<double>(Clock::now() - last).count() > stall))
    {
      kill(pid, SIGKILL);
      Reap(pid);
      return { 'F',
        n > 0 ? "VTK's reader sent more than fits"
              : "VTK's reader hangs: no input or output for " + std::to_string(int(stall)) + " s" };
    }
  }
  const int status = Reap(pid);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !in.empty() &&
    std::string("REM").find(in[0]) != std::string::npos)
  {
    const char kind = in[0];
    in.erase(0, 1);
    return { kind, std::move(in) };
  }
  if (WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    return { 'F',
      signal == SIGKILL ? std::string("VTK's reader was killed")
                        : std::string("VTK's reader crashed: ") + strsignal(signal) };
  }
  return { 'X', "VTK's reader ended with exit status " + std::to_string(WEXITSTATUS(status)),
    status };
}

// While the child goes on, signals sent to this process are for it (a
// terminal's Ctrl-C reaches both already).
pid_t Child = 0;

extern "C" void Forward(int signal, siginfo_t* info, void*)
{
  if (info->si_code == SI_USER || info->si_code == SI_QUEUE)
  {
    kill(Child, signal);
  }
}

[[noreturn]] void EndAs(int status)
{
  if (WIFSIGNALED(status))
  {
    std::signal(WTERMSIG(status), SIG_DFL);
    raise(WTERMSIG(status));
  }
  _exit(WIFEXITED(status) ? WEXITSTATUS(status) : 1);
}

// A pipe whose ends close on exec (a host's other children must not hold
// them) and a child; pid -1 when either cannot be made.
pid_t Fork(int fds[2])
{
  if (InProcess() || pipe(fds) != 0)
  {
    return -1;
  }
  fcntl(fds[0], F_SETFD, FD_CLOEXEC);
  fcntl(fds[1], F_SETFD, FD_CLOEXEC);
  std::cout.flush(); // or both processes would write what is buffered
  std::fflush(nullptr);
  const pid_t pid = fork();
  close(pid == 0 ? fds[0] : fds[1]);
  if (pid < 0)
  {
    close(fds[0]);
  }
  return pid;
}

#endif

} // namespace

std::string ReadIsolated(
  const std::string& file, const char* kind, const std::function<std::string()>& read)
{
#ifdef FLOWRECON_CHILD_READ
  int fds[2];
  const Limits limits = LimitsOf(file);
  const pid_t pid = Fork(fds);
  if (pid == 0)
  {
    EnterChild(limits.Memory);
    const Outcome outcome = Run(file, read);
    WriteAll(fds[1], std::string(1, outcome.Kind));
    WriteAll(fds[1], outcome.Text);
    _exit(0);
  }
  if (pid > 0)
  {
    Outcome outcome = Watch(pid, fds[0], limits.Stall, false);
    close(fds[0]);
    return Result(file, kind, std::move(outcome));
  }
#endif
  return Result(file, kind, Run(file, read));
}

void ReadThenGoOnInChild(
  const std::string& file, const char* kind, const std::function<void()>& read)
{
#ifdef FLOWRECON_CHILD_READ
  int fds[2];
  const Limits limits = LimitsOf(file);
  const pid_t pid = Fork(fds);
  if (pid == 0)
  {
    const auto saved = EnterChild(limits.Memory);
    const auto done = [&]() {
      setrlimit(RLIMIT_AS, &saved.first);
      dup2(saved.second, 2);
      close(saved.second);
      WriteAll(fds[1], "D");
      close(fds[1]);
    };
    try
    {
      read();
    }
    catch (...)
    {
      done();
      throw;
    }
    done();
    return;
  }
  if (pid > 0)
  {
    Child = pid;
    struct sigaction forward = {}, former[4];
    forward.sa_sigaction = Forward;
    forward.sa_flags = SA_SIGINFO | SA_RESTART;
    const int signals[4] = { SIGINT, SIGTERM, SIGHUP, SIGQUIT };
    for (int i = 0; i < 4; ++i)
    {
      sigaction(signals[i], &forward, &former[i]);
    }
    const Outcome outcome = Watch(pid, fds[0], limits.Stall, true);
    close(fds[0]);
    if (outcome.Kind == 'D' || outcome.Kind == 'X')
    {
      EndAs(outcome.Kind == 'D' ? Reap(pid) : outcome.Status);
    }
    for (int i = 0; i < 4; ++i)
    {
      sigaction(signals[i], &former[i], nullptr);
    }
    Result(file, kind, outcome);
  }
#endif
  read();
}

} // namespace reader
} // namespace flowrecon
