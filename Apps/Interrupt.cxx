#include "Interrupt.h"

#include "CliError.h"

#include <atomic>
#include <csignal>

#include <unistd.h> // _exit

namespace flowrecon::cli
{

namespace
{

std::atomic<bool> Requested{ false };

extern "C" void OnInterrupt(int)
{
  if (Requested.exchange(true))
  {
    _exit(ExitInterrupted);
  }
}

} // namespace

void CatchInterrupt()
{
  std::signal(SIGINT, OnInterrupt);
}

bool InterruptRequested()
{
  return Requested.load();
}

void ThrowIfInterrupted()
{
  if (Requested)
  {
    throw Interrupted();
  }
}

} // namespace flowrecon::cli
