// The child process VTK's readers run in (IsolatedRead.h), on reads that need
// no VTK reader to misbehave: what the child returns comes back whole, its
// ReadError as it is, and its crash, abort, hang or runaway allocation as one
// line naming the file, never as the caller's end.
// Usage: TestIsolatedRead WORKDIR
#include "Check.h"

#include "IsolatedRead.h"
#include "PointCloudParsing.h"

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <new>
#include <string>

#include <unistd.h>

namespace
{
using flowrecon::reader::ReadError;
using flowrecon::reader::ReadIsolated;

std::string File;

// The message of the ReadError `read` ends with in its child ("" if none).
std::string Refusal(const std::function<std::string()>& read)
{
  try
  {
    ReadIsolated(File, "test", read);
  }
  catch (const ReadError& e)
  {
    return e.what();
  }
  return std::string();
}

void ExpectRefusal(const std::function<std::string()>& read, const std::string& words)
{
  const std::string message = Refusal(read);
  const bool ok = message.rfind(File + ": ", 0) == 0 && message.find(words) != std::string::npos &&
    message.find('\n') == std::string::npos;
  CHECK(ok);
  if (!ok)
  {
    std::cout << "  message [" << message << "], expected [" << words << "]\n";
  }
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cout << "usage: TestIsolatedRead WORKDIR\n";
    return EXIT_FAILURE;
  }
  File = std::string(argv[1]) + "/isolated.txt";
  std::ofstream(File) << "a small input\n";
  const pid_t caller = getpid();

  // The bytes come back whole (more than a pipe holds at once), from another process.
  std::string big(50 << 20, '\0');
  for (std::size_t i = 0; i < big.size(); ++i)
  {
    big[i] = static_cast<char>(i * 7919 % 251);
  }
  CHECK(ReadIsolated(File, "test", [&big]() { return big; }) == big);
  CHECK(ReadIsolated(File, "test", []() { return std::string(); }).empty());
  const std::string pid =
    ReadIsolated(File, "test", []() { return std::to_string(static_cast<long>(getpid())); });
  CHECK(pid != std::to_string(static_cast<long>(caller)));

  // A reader's own error, as it is.
  CHECK(Refusal([]() -> std::string { throw ReadError("some file:3: bad line"); }) ==
    "some file:3: bad line");

  // What would end the caller ends the child: one line each. (A crash under
  // AddressSanitizer ends the child with its own exit status.)
  ExpectRefusal([]() -> std::string { std::abort(); },
    ": cannot read test file (VTK's reader crashed: Aborted)");
  ExpectRefusal(
    []() -> std::string {
      std::raise(SIGSEGV);
      return std::string();
    },
    ": cannot read test file (VTK's reader ");
  ExpectRefusal([]() -> std::string { _exit(3); },
    ": cannot read test file (VTK's reader ended with exit status 3)");
  // More than 1 GB + 1100 times the input (15 bytes), as VTK's arrays
  // allocate (malloc: under AddressSanitizer a failed `new` aborts).
  ExpectRefusal(
    []() {
      void* huge = std::malloc(std::size_t(3) << 30);
      const bool allocated = huge != nullptr;
      std::free(huge);
      if (!allocated)
      {
        throw std::bad_alloc();
      }
      return std::string();
    },
    ": out of memory");
  ExpectRefusal([]() -> std::string { throw std::bad_alloc(); }, ": out of memory");
  // A loop without input or output is stopped after 10 s.
  ExpectRefusal(
    []() -> std::string {
      for (volatile unsigned long i = 0;; i = i + 1)
      {
      }
    },
    ": cannot read test file (VTK's reader hangs: no input or output for 10 s)");
  CHECK(getpid() == caller);

  // FLOWRECON_READ_IN_PROCESS: the read runs here (to debug a reader).
  setenv("FLOWRECON_READ_IN_PROCESS", "1", 1);
  CHECK(ReadIsolated(File, "test", []() { return std::to_string(static_cast<long>(getpid())); }) ==
    std::to_string(static_cast<long>(caller)));
  CHECK(Refusal([]() -> std::string { throw std::bad_alloc(); }) == File + ": out of memory");
  unsetenv("FLOWRECON_READ_IN_PROCESS");
  return check::Finish("TestIsolatedRead");
}
