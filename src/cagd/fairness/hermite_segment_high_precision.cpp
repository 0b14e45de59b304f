// segment_energy_high_precision: E, L, J of the unit-chord Hermite segment in 50 digits.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "cagd/fairness/hermite_segment.hpp"

namespace cagd::fairness {

namespace {
using Real = boost::multiprecision::cpp_bin_float_50;

struct Vec {
    Real x, y;
};
}  // namespace

SegmentEnergyDigits segment_energy_high_precision(double theta0, double theta1, double r0, double r1) {
    const UnitChordHermite seg(theta0, theta1, r0, r1);  // validates; gives the graded pieces
    if (has_cusp(seg))
        fail_input("cagd::fairness::segment_energy_high_precision",
                   "the segment has a cusp: its strain energy diverges");
    const Real R0(r0), R1(r1);
    const Vec u0{cos(Real(theta0)), sin(Real(theta0))}, u1{cos(Real(theta1)), sin(Real(theta1))};
    // Exact directions at multiples of π/2 as in the double path.
    const Vec U0{abs(u0.x) < Real(1e-15) ? Real(0) : u0.x, abs(u0.y) < Real(1e-15) ? Real(0) : u0.y};
    const Vec U1{abs(u1.x) < Real(1e-15) ? Real(0) : u1.x, abs(u1.y) < Real(1e-15) ? Real(0) : u1.y};
    const Vec A{R0 * U0.x, R0 * U0.y};
    const Vec B{6 - 4 * R0 * U0.x - 2 * R1 * U1.x, -4 * R0 * U0.y - 2 * R1 * U1.y};
    const Vec C{-6 + 3 * R0 * U0.x + 3 * R1 * U1.x, 3 * R0 * U0.y + 3 * R1 * U1.y};
    const auto speed = [&](const Real& t) {
        const Real x = A.x + t * (B.x + t * C.x), y = A.y + t * (B.y + t * C.y);
        return sqrt(x * x + y * y);
    };
    const auto bend = [&](const Real& t) {
        const Real x = A.x + t * (B.x + t * C.x), y = A.y + t * (B.y + t * C.y);
        const Real xx = B.x + 2 * t * C.x, yy = B.y + 2 * t * C.y;
        const Real k = xx * y - x * yy;
        const Real g = x * x + y * y;
        return k * k / (g * g * sqrt(g));
    };
    using Rule = boost::math::quadrature::gauss_kronrod<Real, 61>;
    const std::vector<double> br = integration_breaks(seg);
    Real length = 0, energy = 0;
    for (std::size_t p = 0; p + 1 < br.size(); ++p) {
        length += Rule::integrate(speed, Real(br[p]), Real(br[p + 1]), 25, Real(1e-40));
        energy += Rule::integrate(bend, Real(br[p]), Real(br[p + 1]), 25, Real(1e-40));
    }
    const Real j = length * length * energy;
    SegmentEnergyDigits out;
    out.strain_energy = energy.str(40, std::ios_base::scientific);
    out.length = length.str(40, std::ios_base::scientific);
    out.pseudo_energy = j.str(40, std::ios_base::scientific);
    out.strain_energy_value = static_cast<double>(energy);
    out.length_value = static_cast<double>(length);
    out.pseudo_energy_value = static_cast<double>(j);
    return out;
}

}  // namespace cagd::fairness
