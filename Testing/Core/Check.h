// Minimal test helpers: a failed check prints where and what, and the test exits 1.
#ifndef flowrecon_Check_h
#define flowrecon_Check_h

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace check
{
inline int& Failures()
{
  static int n = 0;
  return n;
}
inline int Finish(const char* name)
{
  if (Failures() == 0)
  {
    std::cout << name << ": all checks passed\n";
    return EXIT_SUCCESS;
  }
  std::cout << name << ": " << Failures() << " check(s) failed\n";
  return EXIT_FAILURE;
}
} // namespace check

#define CHECK(cond)                                                                             \
  do                                                                                            \
  {                                                                                             \
    if (!(cond))                                                                                \
    {                                                                                           \
      std::cout << __FILE__ << ":" << __LINE__ << ": check failed: " #cond "\n";                \
      ++check::Failures();                                                                      \
    }                                                                                           \
  } while (0)

#define CHECK_NEAR(a, b, tol)                                                                   \
  do                                                                                            \
  {                                                                                             \
    const double va_ = (a), vb_ = (b);                                                          \
    if (!(std::fabs(va_ - vb_) <= (tol)))                                                       \
    {                                                                                           \
      std::cout << __FILE__ << ":" << __LINE__ << ": " #a " = " << va_ << " but expected " #b  \
                << " = " << vb_ << "\n";                                                        \
      ++check::Failures();                                                                      \
    }                                                                                           \
  } while (0)

/// Fails unless `statement` throws `exception`.
#define CHECK_THROWS(statement, exception)                                                      \
  do                                                                                            \
  {                                                                                             \
    bool threw_ = false;                                                                        \
    try                                                                                         \
    {                                                                                           \
      statement;                                                                                \
    }                                                                                           \
    catch (const exception&)                                                                    \
    {                                                                                           \
      threw_ = true;                                                                            \
    }                                                                                           \
    if (!threw_)                                                                                \
    {                                                                                           \
      std::cout << __FILE__ << ":" << __LINE__ << ": expected " #exception " from " #statement  \
                << "\n";                                                                        \
      ++check::Failures();                                                                      \
    }                                                                                           \
  } while (0)

#endif
