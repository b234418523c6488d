// The walks' exact number type against GMP's canonical rationals (the oracle):
// every operation, signs, truncation to double and reduction, on random values
// of both signs, zeros, extreme exponents, shared denominators (the fast paths)
// and long chains of Moebius maps as a walk builds them.
#include "Check.h"

#include "VoronoiWalk.h"

#include <CGAL/Gmpq.h>

#include <cmath>
#include <random>

using namespace flowrecon;

namespace
{

CGAL::Gmpq Q(double x)
{
  return CGAL::Gmpq(x);
}

bool Same(const ExactRational& r, const CGAL::Gmpq& q)
{
  return r.Quotient() == q && static_cast<int>(r.Sign()) == static_cast<int>(CGAL::sign(q)) &&
    r.ToDouble() == q.to_double();
}

} // namespace

int main()
{
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto value = [&]() {
    switch (g() % 6)
    {
      case 0:
        return 0.0;
      case 1:
        return std::ldexp(u(g), static_cast<int>(g() % 2000) - 1000); // extreme exponents
      case 2:
        return std::floor(8 * u(g)); // small integers: equal denominators, exact zeros
      default:
        return u(g);
    }
  };
  long mismatches = 0, divisions = 0;
  for (int trial = 0; trial < 50000; ++trial)
  {
    const double x = value(), y = value(), z = value(), w = value();
    const ExactRational a(x), b(y), c(z), d(w);
    const CGAL::Gmpq A = Q(x), B = Q(y), C = Q(z), D = Q(w);
    mismatches += !Same(a + b, A + B) + !Same(a - b, A - B) + !Same(a * b, A * B) + !Same(-a, -A);
    // Shared denominators: (a / c) and (b / c) take the equal-denominator paths.
    if (z != 0)
    {
      ++divisions;
      const ExactRational ac = a / c, bc = b / c;
      const CGAL::Gmpq AC = A / C, BC = B / C;
      mismatches += !Same(ac, AC) + !Same(ac + bc, AC + BC) + !Same(ac - bc, AC - BC) +
        !Same(ac * bc, AC * BC) + !Same(ac * b, AC * B) + !Same(b * ac, B * AC) +
        !Same(ac + b, AC + B) + !Same(b - ac, B - AC);
      if (y != 0)
      {
        mismatches += !Same(ac / bc, AC / BC) + !Same(ac / b, AC / B);
      }
      if (x != 0)
      {
        mismatches += !Same(b / ac, B / AC);
      }
      const ExactRational r = ((a + b) * (c - d) / c - b / c).Reduced();
      const CGAL::Gmpq R = (A + B) * (C - D) / C - B / C;
      mismatches += !Same(r, R);
      // Reduced means canonical: the same terms as GMP's.
      mismatches += !(static_cast<CGAL::Gmpq>(r.Numerator()) == R.numerator() &&
        static_cast<CGAL::Gmpq>(r.Denominator()) == R.denominator());
    }
  }
  CHECK(divisions > 10000);
  CHECK(mismatches == 0);

  // Chains of Moebius maps, as along a walk: the terms outgrow a double (the
  // reduction path) and the value stays exact.
  long chainMismatches = 0, parallel = 0, enclosureMisses = 0, hugeTerms = 0;
  for (int chain = 0; chain < 200; ++chain)
  {
    ExactRational lambda(u(g));
    CGAL::Gmpq L = lambda.Quotient();
    for (int step = 0; step < 60; ++step)
    {
      const double ca = u(g), cb = u(g), cc = u(g), cd = u(g), den = 1 + std::abs(u(g));
      const ExactRational a = ExactRational(ca) / ExactRational(den), b(cb), c(cc),
                          d = ExactRational(cd) / ExactRational(den * 3);
      const CGAL::Gmpq A = Q(ca) / Q(den), B = Q(cb), C = Q(cc), D = Q(cd) / Q(den * 3);
      if (CGAL::sign(C + D * L) == CGAL::ZERO)
      {
        ++parallel;
        break;
      }
      lambda = Moebius(a, b, c, d, lambda);
      L = -(A + B * L) / (C + D * L);
      chainMismatches += !Same(lambda, L);
      // What exact walks enclose lambda in when its terms are past doubles
      // (FilteredJudge): the truncated quotient and its neighbours.
      const double x = lambda.ToDouble();
      hugeTerms += !std::isfinite(lambda.Numerator().to_interval().second) ||
        !std::isfinite(lambda.Denominator().to_interval().second);
      enclosureMisses += !(Q(std::nextafter(x, -HUGE_VAL)) <= L && L <= Q(std::nextafter(x, HUGE_VAL)));
    }
  }
  CHECK(chainMismatches == 0);
  CHECK(enclosureMisses == 0);
  // Terms past the range of doubles, quotients of any size.
  for (int k = 0; k < 2000; ++k)
  {
    const int e = 600 + static_cast<int>(g() % 400);
    const ExactRational n = ExactRational(std::ldexp(u(g), e)) * ExactRational(std::ldexp(u(g), e));
    const ExactRational d = ExactRational(std::ldexp(u(g), e)) * ExactRational(std::ldexp(u(g), e)) +
      ExactRational(std::ldexp(u(g), e - 700));
    if (d.Sign() == CGAL::ZERO)
    {
      continue;
    }
    const ExactRational r = n / d * ExactRational(std::ldexp(1.0, static_cast<int>(g() % 1200) - 600));
    const double x = r.ToDouble();
    hugeTerms += !std::isfinite(r.Numerator().to_interval().second) ||
      !std::isfinite(r.Denominator().to_interval().second);
    const CGAL::Gmpq R = r.Quotient();
    enclosureMisses += !std::isfinite(x) ||
      !(Q(std::nextafter(x, -HUGE_VAL)) <= R && R <= Q(std::nextafter(x, HUGE_VAL)));
  }
  CHECK(enclosureMisses == 0);
  CHECK(hugeTerms > 1000);
  CHECK(parallel == 0);

  // Zero denominators are refused, not divided by.
  bool threw = false;
  try
  {
    (void)(ExactRational(1.0) / ExactRational(0.0));
  }
  catch (const std::domain_error&)
  {
    threw = true;
  }
  CHECK(threw);
  return check::Finish("TestExactRational");
}
