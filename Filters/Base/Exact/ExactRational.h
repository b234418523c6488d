// The number type of the walks' exact fallback: a quotient of two CGAL::Mpzf
// (integers times a power of two, so every double is exact), not reduced.
//
// Why not Gmpq or CGAL::Quotient: the walks' expressions are dot and cross
// products of points whose coordinates share one denominator (a circumcentre
// is X / (2 |n|^2)). Gmpq finds that common factor again with a gcd at every
// operation (measured: gcds were two thirds of `flowrecon complex` on 10^5
// sphere points, whose flow lines cross the crowded centre exactly);
// Quotient<Mpzf> multiplies the equal denominators together and ran twice as
// slow as Gmpq. Here a sum of equal denominators keeps it, and the one value
// that is carried from step to step (a walk's lambda) is reduced once per step
// (Reduced()).
#ifndef flowrecon_ExactRational_h
#define flowrecon_ExactRational_h

#include <CGAL/Mpzf.h>
#include <CGAL/enum.h>
#include <CGAL/Gmpq.h>

#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace flowrecon
{

class ExactRational
{
public:
  ExactRational()
    : N(0)
    , D(1)
  {
  }
  explicit ExactRational(double x)
    : N(x)
    , D(1)
  {
  }
  explicit ExactRational(int x)
    : N(x)
    , D(1)
  {
  }
  /// n / d, d != 0.
  ExactRational(CGAL::Mpzf n, CGAL::Mpzf d)
    : N(std::move(n))
    , D(std::move(d))
  {
    if (this->D.is_zero())
    {
      throw std::domain_error("exact rational: division by zero");
    }
    if (this->D.sign() == CGAL::NEGATIVE)
    {
      this->N = -this->N;
      this->D = -this->D;
    }
  }

  const CGAL::Mpzf& Numerator() const { return this->N; }
  const CGAL::Mpzf& Denominator() const { return this->D; } ///< always > 0

  CGAL::Sign Sign() const { return this->N.sign(); }

  /// The same value with numerator and denominator without common factor.
  ExactRational Reduced() const
  {
    const CGAL::Gmpq q = this->Quotient();
    return ExactRational(FromGmpz(q.numerator()), FromGmpz(q.denominator()));
  }

  /// Truncated to a double, as GMP's mpq_get_d, for any sizes of the terms.
  double ToDouble() const
  {
    // N / D = (a / 2^i) / (b / 2^j) with integers a, b: the quotient of a and b
    // scaled to 54-55 bits and truncated, then truncated again to 53 bits by
    // mpz_get_d, is the truncation of the exact value (no gcd, unlike Gmpq).
    if (this->N.is_zero())
    {
      return 0;
    }
    const CGAL::Gmpq n = static_cast<CGAL::Gmpq>(this->N), d = static_cast<CGAL::Gmpq>(this->D);
    mpz_t a, b, q;
    mpz_init_set(a, mpq_numref(n.mpq()));
    mpz_init_set(b, mpq_numref(d.mpq()));
    mpz_init(q);
    const long shift = static_cast<long>(mpz_sizeinbase(b, 2)) - static_cast<long>(mpz_sizeinbase(a, 2)) + 54;
    if (shift >= 0)
    {
      mpz_mul_2exp(a, a, static_cast<mp_bitcnt_t>(shift));
    }
    else
    {
      mpz_mul_2exp(b, b, static_cast<mp_bitcnt_t>(-shift));
    }
    mpz_tdiv_q(q, a, b);
    // Powers of two left in the denominators: 2^j / 2^i, as exponents.
    const long i = static_cast<long>(mpz_sizeinbase(mpq_denref(n.mpq()), 2)) - 1;
    const long j = static_cast<long>(mpz_sizeinbase(mpq_denref(d.mpq()), 2)) - 1;
    const double x = std::ldexp(mpz_get_d(q), static_cast<int>(j - i - shift));
    mpz_clears(a, b, q, nullptr);
    // Below the normal range ldexp rounds instead of truncating: GMP then.
    return std::isfinite(x) && std::abs(x) >= DBL_MIN ? x : this->Quotient().to_double();
  }

  /// As a canonical GMP rational.
  CGAL::Gmpq Quotient() const
  {
    return static_cast<CGAL::Gmpq>(this->N) / static_cast<CGAL::Gmpq>(this->D);
  }

  friend ExactRational operator-(const ExactRational& a) { return ExactRational(-a.N, a.D, Raw()); }
  friend ExactRational operator+(const ExactRational& a, const ExactRational& b)
  {
    return Sum(a, b, 1);
  }
  friend ExactRational operator-(const ExactRational& a, const ExactRational& b)
  {
    return Sum(a, b, -1);
  }
  friend ExactRational operator*(const ExactRational& a, const ExactRational& b)
  {
    if (a.D.is_one())
    {
      return ExactRational(a.N * b.N, b.D, Raw());
    }
    if (b.D.is_one())
    {
      return ExactRational(a.N * b.N, a.D, Raw());
    }
    return ExactRational(a.N * b.N, a.D * b.D, Raw());
  }
  friend ExactRational operator/(const ExactRational& a, const ExactRational& b)
  {
    if (a.D == b.D)
    {
      return ExactRational(a.N, b.N);
    }
    return ExactRational(b.D.is_one() ? a.N : a.N * b.D, a.D.is_one() ? b.N : a.D * b.N);
  }

private:
  struct Raw
  {
  };
  ExactRational(CGAL::Mpzf n, CGAL::Mpzf d, Raw)
    : N(std::move(n))
    , D(std::move(d))
  {
  }

  /// CGAL 5.5's Mpzf(Gmpz) drops the sign and mishandles zero.
  static CGAL::Mpzf FromGmpz(const CGAL::Gmpz& z)
  {
    if (z.sign() == CGAL::ZERO)
    {
      return CGAL::Mpzf(0);
    }
    const CGAL::Mpzf magnitude(z.sign() == CGAL::NEGATIVE ? CGAL::Gmpz(-z) : z);
    return z.sign() == CGAL::NEGATIVE ? -magnitude : magnitude;
  }

  static ExactRational Sum(const ExactRational& a, const ExactRational& b, int s)
  {
    if (a.D == b.D)
    {
      return ExactRational(s > 0 ? a.N + b.N : a.N - b.N, a.D, Raw());
    }
    if (b.D.is_one())
    {
      const CGAL::Mpzf t = b.N * a.D;
      return ExactRational(s > 0 ? a.N + t : a.N - t, a.D, Raw());
    }
    if (a.D.is_one())
    {
      const CGAL::Mpzf t = a.N * b.D;
      return ExactRational(s > 0 ? t + b.N : t - b.N, b.D, Raw());
    }
    const CGAL::Mpzf t = a.N * b.D, u = b.N * a.D;
    return ExactRational(s > 0 ? t + u : t - u, a.D * b.D, Raw());
  }

  CGAL::Mpzf N, D;
};

} // namespace flowrecon

#endif
