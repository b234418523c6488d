// Ctrl-C: the first press asks the running computation to stop (ProgressLine
// forwards the request to VTK filters and the core); a second one exits at once.
#ifndef flowrecon_cli_Interrupt_h
#define flowrecon_cli_Interrupt_h

namespace flowrecon::cli
{

/// Installs the SIGINT handler; the first thing main does.
void CatchInterrupt();

/// Whether Ctrl-C was pressed.
bool InterruptRequested();

/// Throws Interrupted() if Ctrl-C was pressed.
void ThrowIfInterrupted();

} // namespace flowrecon::cli

#endif
