#pragma once
// The Appendix B benchmarks of `shellpack bench-mechanics CASE`, each a CSV with the computed
// curve beside the analytic one (lib/elasticity):
//   sphere          B.5.1, Fig. B.4A  inflated sphere, strain vs dP/E, SVK and spring meshes
//   poisson         B.5.2, Fig. B.4B  uniaxially stretched sheet, measured nu vs input nu
//   plate-point     B.5.3, Fig. B.5   clamped disc, central point load, deflection profile
//   plate-uniform   B.5.3, Fig. B.6   clamped disc, uniform load, deflection profile
//   plate-large     B.5.4, Fig. B.7   clamped disc, w_max/t vs P* = (q/E)(R0/t)^4
//   plates-contact  B.6,   Fig. B.9   inflated membrane squeezed between plates, F and P vs X
//   buckling        B.7,   Fig. B.10  sphere under growing external pressure, p_buckle/p_c
// `quick` runs smaller meshes and fewer loads (seconds; the tests); otherwise the thesis's sizes.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace cmp::shellbench {

// The case names, in the order above.
std::vector<std::string> mechanics_benchmark_names();

// Throws cmp::UsageError "unknown benchmark 'x' (known: ...)".
void check_mechanics_benchmark(const std::string& name);

// Runs the case and writes its table to out; note(text) reports progress.
void run_mechanics_benchmark(const std::string& name, bool quick, std::ostream& out, const std::string& provenance,
                             const std::function<void(const std::string&)>& note = {});

}  // namespace cmp::shellbench
