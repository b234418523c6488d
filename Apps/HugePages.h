// Transparent huge pages for the whole process. Most of a run's system time is
// the kernel zeroing and mapping fresh 4 KB pages (triangulation blocks, node
// and arc arrays); glibc's malloc asks for 2 MB pages when told so by its
// tunable glibc.malloc.hugetlb=1, which it reads only at start-up.
#ifndef flowrecon_cli_HugePages_h
#define flowrecon_cli_HugePages_h

namespace flowrecon::cli
{

/// Starts this program again with glibc.malloc.hugetlb=1 added to
/// GLIBC_TUNABLES, when the kernel gives huge pages only to memory that asks
/// for them ("[madvise]" mode) and the tunables do not already say anything
/// about it (GLIBC_TUNABLES=glibc.malloc.hugetlb=0 keeps 4 KB pages). Returns
/// when it does not apply or the new start fails; the run then goes on as is.
void RestartWithHugePages(char* argv[]);

} // namespace flowrecon::cli

#endif
