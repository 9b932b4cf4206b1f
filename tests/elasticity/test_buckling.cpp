#include "elasticity/buckling.hpp"

#include "core/errors.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace cmp::elasticity;

TEST_CASE("buckling pressure and Foppl-von Karman number: the reference numbers of B.7", "[elasticity][buckling]") {
  const double nu = 1.0 / 3.0;
  const double gammas[] = {1e3, 5e3, 1e4, 5e4};
  const double pc_R_over_Y[] = {0.12649, 0.05657, 0.04000, 0.01789};
  const double R_over_t[] = {9.682, 21.651, 30.619, 68.465};
  for (int i = 0; i < 4; ++i) {
    INFO("gamma = " << gammas[i]);
    const double rt = radius_over_thickness(gammas[i], nu);
    CHECK(rt == Approx(R_over_t[i]).margin(5e-4));
    const Sheet s{25e6, nu, 0.1};
    const double R = rt * s.thickness;
    CHECK(foppl_von_karman(s, R) == Approx(gammas[i]).epsilon(1e-12));
    const double pc = buckling_pressure(s, R);
    CHECK(pc * R / s.stretching_modulus() == Approx(pc_R_over_Y[i]).margin(5e-6));
    // The three forms of the classical result.
    CHECK(pc == Approx(4 * s.stretching_modulus() / (R * std::sqrt(gammas[i]))).epsilon(1e-12));
    CHECK(pc == Approx(2 * s.youngs_modulus * std::pow(s.thickness / R, 2) / std::sqrt(3 * (1 - nu * nu))).epsilon(1e-12));
  }
  CHECK_THROWS_AS(buckling_pressure(1.0, -1.0, 1.0), std::domain_error);
}

TEST_CASE("spring and hinge calibrations round-trip", "[elasticity][buckling]") {
  CHECK(spring_stretching_modulus(spring_constant(3.0)) == Approx(3.0).epsilon(1e-15));
  CHECK(spring_constant(2.0 / std::sqrt(3.0)) == Approx(1.0).epsilon(1e-15));
  CHECK(hinge_bending_rigidity(1.0, HingeCalibration::Cylinder) == Approx(std::sqrt(3.0) / 2).epsilon(1e-15));
  CHECK(hinge_bending_rigidity(1.0, HingeCalibration::Sphere) == Approx(1 / (2 * std::sqrt(3.0))).epsilon(1e-15));
  // lib/shell's hinge-uniform stiffness 2 kappa/sqrt(3) is the Cylinder calibration.
  CHECK(hinge_constant(1.0, HingeCalibration::Cylinder) == Approx(2 / std::sqrt(3.0)).epsilon(1e-15));
  for (auto c : {HingeCalibration::Cylinder, HingeCalibration::Sphere})
    CHECK(hinge_bending_rigidity(hinge_constant(0.7, c), c) == Approx(0.7).epsilon(1e-15));
}

TEST_CASE("sheet validation and the Poisson ratio of measured strains", "[elasticity]") {
  CHECK_NOTHROW(validate(Sheet{1.0, 0.5, 0.1}, "x"));
  CHECK_THROWS_AS(validate(Sheet{1.0, 0.6, 0.1}, "x"), cmp::UsageError);
  CHECK_THROWS_AS(validate(Sheet{1.0, -1.0, 0.1}, "x"), cmp::UsageError);
  CHECK_THROWS_AS(validate(Sheet{0.0, 0.3, 0.1}, "x"), cmp::UsageError);
  CHECK_THROWS_AS(validate(Sheet{1.0, 0.3, NAN}, "x"), cmp::UsageError);
  CHECK(Sheet{25e6, 1.0 / 3.0, 0.1}.bending_rigidity() == Approx(2343.75).epsilon(1e-12));
  CHECK(poisson_ratio_from_strains(0.01, -0.003) == Approx(0.3).epsilon(1e-14));
  CHECK_THROWS_AS(poisson_ratio_from_strains(0.0, -0.003), cmp::ComputationError);
}
