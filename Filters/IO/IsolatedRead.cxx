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
#include <filesystem>
#include <fstream>
#include <iostream>
#include <fcntl.h>
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

std::string Result(const std::string& file, Outcome outcome)
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
  return std::move(outcome.Text);
}

#ifdef FLOWRECON_CHILD_READ

bool InProcess()
{
  const char* value = std::getenv("FLOWRECON_READ_IN_PROCESS");
  return value && *value && std::strcmp(value, "0") != 0;
}

void WriteAll(int fd, const char* data, std::size_t size)
{
  while (size > 0)
  {
    const ssize_t n = write(fd, data, size);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return; // the parent is gone
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

// A frame: its kind, its length (8 bytes, this machine's order) and its text.
void Send(int fd, const Outcome& outcome)
{
  char header[9] = { outcome.Kind };
  const std::uint64_t size = outcome.Text.size();
  std::memcpy(header + 1, &size, 8);
  WriteAll(fd, header, sizeof(header));
  WriteAll(fd, outcome.Text.data(), outcome.Text.size());
}

// What a child may take: memory and seconds without input or output.
struct Limits
{
  double Memory;
  double Stall;
};

// The bytes a reader of `file` takes in: the file and, for a composite or
// parallel XML file, the files it names (file="..." or Source="...").
double InputBytes(const std::string& file)
{
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  double bytes = error ? 0.0 : static_cast<double>(size);
  const std::string extension = Lower(std::filesystem::path(file).extension().string());
  if (error || (extension != ".vtm" && extension != ".vthb" && extension.compare(0, 4, ".pvt") != 0))
  {
    return bytes;
  }
  std::ifstream in(file, std::ios::binary);
  std::string text(static_cast<std::size_t>(std::min<std::uintmax_t>(size, 1 << 24)), '\0');
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  for (const char* key : { "file", "Source" })
  {
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1))
    {
      const std::size_t equals = text.find_first_not_of(" \t\r\n", at + std::strlen(key));
      const std::size_t quote = text.find_first_not_of(" \t\r\n", equals + 1);
      if (equals < text.size() && text[equals] == '=' && quote < text.size() &&
        (text[quote] == '"' || text[quote] == '\''))
      {
        const std::size_t end = text.find(text[quote], quote + 1);
        const auto named = std::filesystem::path(file).parent_path() /
          text.substr(quote + 1, end == std::string::npos ? 0 : end - quote - 1);
        const std::uintmax_t more = std::filesystem::file_size(named, error);
        bytes += error ? 0.0 : static_cast<double>(more);
      }
    }
  }
  return bytes;
}

// Memory: what this process could still allocate, and at most 1 GB plus 1100
// times the input (zlib, the strongest compressor VTK's XML writers use for
// point data, expands at most 1032 times): a count VTK believes makes it
// allocate and fill that much. Stall: 10 s plus 1 s per 100 MB of input.
Limits LimitsOf(const std::string& file)
{
  const double input = InputBytes(file);
  return { std::min(AvailableMemory(), 1e9 + 1100 * input), 10 + input / 1e8 };
}

// The child ends with the caller and reports no crash to a fuzzer; its
// address space may grow by `memory`. Returns the limit to restore.
rlimit EnterChild(double memory)
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
  rlimit limit{};
  getrlimit(RLIMIT_AS, &limit);
  const rlimit saved = limit;
  long long pages = 0;
  std::ifstream("/proc/self/statm") >> pages; // the address space in use
  const double cap = static_cast<double>(pages) * static_cast<double>(sysconf(_SC_PAGESIZE)) + memory;
  if (pages > 0 && std::isfinite(memory) && cap < static_cast<double>(limit.rlim_cur))
  {
    limit.rlim_cur = static_cast<rlim_t>(cap);
    setrlimit(RLIMIT_AS, &limit);
  }
  return saved;
}

// Sends the child's messages (a C library's crash report) to /dev/null, since
// the caller reports in one line; returns a copy of the former stderr.
int Silence()
{
  const int former = dup(2);
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0)
  {
    dup2(null, 2);
    close(null);
  }
  return former;
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

// Reads the child's frames from `fd` until it ends or, `goesOn`, says 'D';
// stops a child that neither reads nor writes for `stall` seconds (VTK 9.2's
// legacy reader loops forever on 256 blanks).
Outcome Watch(pid_t pid, int fd, double stall, bool goesOn)
{
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  long long seen = -2;
  Outcome outcome;
  std::string header; // a frame's kind and length
  std::uint64_t length = 0;
  for (;;)
  {
    pollfd ready{ fd, POLLIN, 0 };
    const int polled = poll(&ready, 1, 1000);
    if (polled == 0 || (polled < 0 && errno == EINTR))
    {
      const long long activity = Activity(pid);
      if (activity != seen)
      {
        seen = activity;
        last = Clock::now();
      }
      else if (activity >= 0 && std::chrono::duration<double>(Clock::now() - last).count() > stall)
      {
        kill(pid, SIGKILL);
        Reap(pid);
        return { 'F', "VTK's reader hangs: no input or output for " + std::to_string(int(stall)) + " s" };
      }
      continue;
    }
    char buffer[1 << 16];
    const ssize_t n = polled < 0 ? -1 : read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      break; // the child has ended
    }
    for (const char* p = buffer; p < buffer + n;)
    {
      if (header.empty() && *p == 'D' && goesOn)
      {
        return { 'D' };
      }
      if (header.size() < 9)
      {
        header += *p++;
        if (header.size() == 9)
        {
          std::memcpy(&length, header.data() + 1, 8);
          if (length > AvailableMemory() || std::string("REM").find(header[0]) == std::string::npos)
          {
            kill(pid, SIGKILL);
            Reap(pid);
            return { 'F', "VTK's reader sent garbled data" };
          }
          outcome = { header[0] };
          outcome.Text.reserve(length);
        }
        continue;
      }
      const std::size_t take = std::min<std::size_t>(buffer + n - p, length - outcome.Text.size());
      outcome.Text.append(p, take);
      p += take;
    }
  }
  const int status = Reap(pid);
  if (header.size() == 9 && outcome.Text.size() == length)
  {
    return outcome;
  }
  if (WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    return { 'F', signal == SIGKILL ? std::string("VTK's reader was killed")
                                    : std::string("VTK's reader crashed: ") + strsignal(signal) };
  }
  return { 'X', "VTK's reader ended with exit status " + std::to_string(WEXITSTATUS(status)), status };
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

#endif

} // namespace

std::string ReadIsolated(
  const std::string& file, const char* kind, const std::function<std::string()>& read)
{
#ifdef FLOWRECON_CHILD_READ
  int fds[2];
  if (!InProcess() && pipe(fds) == 0)
  {
    fcntl(fds[0], F_SETFD, FD_CLOEXEC);
    fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    const Limits limits = LimitsOf(file);
    const pid_t pid = fork();
    if (pid == 0)
    {
      close(fds[0]);
      EnterChild(limits.Memory);
      Silence();
      Send(fds[1], Run(file, read));
      _exit(0);
    }
    close(fds[1]);
    Outcome outcome;
    if (pid > 0)
    {
      outcome = Watch(pid, fds[0], limits.Stall, false);
    }
    close(fds[0]);
    if (outcome.Kind == 'F' || outcome.Kind == 'X')
    {
      Fail(file, 0, std::string("cannot read ") + kind + " file (" + outcome.Text + ")");
    }
    if (pid > 0)
    {
      return Result(file, std::move(outcome));
    }
  }
#endif
  return Result(file, Run(file, read));
}

void ReadThenGoOnInChild(
  const std::string& file, const char* kind, const std::function<void()>& read)
{
#ifdef FLOWRECON_CHILD_READ
  int fds[2];
  if (!InProcess() && pipe(fds) == 0)
  {
    fcntl(fds[0], F_SETFD, FD_CLOEXEC);
    fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    const Limits limits = LimitsOf(file);
    std::cout.flush(); // or both processes would write what is buffered
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0)
    {
      close(fds[0]);
      const rlimit limit = EnterChild(limits.Memory);
      const int stderrCopy = Silence();
      const auto done = [&]() {
        setrlimit(RLIMIT_AS, &limit);
        dup2(stderrCopy, 2);
        close(stderrCopy);
        WriteAll(fds[1], "D", 1);
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
    close(fds[1]);
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
      if (outcome.Kind == 'D')
      {
        EndAs(Reap(pid));
      }
      if (outcome.Kind == 'X')
      {
        EndAs(outcome.Status);
      }
      for (int i = 0; i < 4; ++i)
      {
        sigaction(signals[i], &former[i], nullptr);
      }
      Fail(file, 0, std::string("cannot read ") + kind + " file (" + outcome.Text + ")");
    }
    close(fds[0]);
  }
#endif
  read();
}

} // namespace reader
} // namespace flowrecon
