#include "spheres/contact_styles.hpp"

#include "spheres/hertz_spheres.hpp"

#include "core/registry.hpp"

namespace cmp::spheres {

namespace {

// HertzSpheres behind the force-field interface (its pair list follows the states asked for).
class HertzSpheresField final : public ForceField {
 public:
  HertzSpheresField(const Eigen::Vector3d& box, const Eigen::VectorXd& radii, const HertzMaterial& material)
      : system_(box, radii, material) {}
  std::string name() const override { return "hertz"; }
  std::size_t state_size() const override { return 3 * static_cast<std::size_t>(system_.size()); }
  double energy(std::span<const double> x) const override {
    check_sizes(x);
    return system_.evaluate(as_vector(x)).energy;
  }
  void add_gradient(std::span<const double> x, std::span<double> g) const override {
    check_sizes(x, g);
    system_.forces(as_vector(x), f_);
    for (std::size_t k = 0; k < g.size(); ++k) g[k] -= f_[static_cast<Eigen::Index>(k)];
  }

 private:
  static Eigen::VectorXd as_vector(std::span<const double> x) {
    return Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  }
  mutable HertzSpheres system_;
  mutable Eigen::VectorXd f_;
};

const ContactStyle kStyles[] = {
    {"hertz", "Hertz repulsion of overlapping spheres, U = (8/15) E* sqrt(R*) h^(5/2) (B.60, 5.5.1)",
     [](const Eigen::Vector3d& box, const Eigen::VectorXd& radii,
        const HertzMaterial& material) -> std::unique_ptr<ForceField> {
       return std::make_unique<HertzSpheresField>(box, radii, material);
     }},
};

}  // namespace

std::span<const ContactStyle> contact_styles() { return kStyles; }
const ContactStyle& contact_style(const std::string& name) {
  return find_style(contact_styles(), name, "sphere contact model");
}

}  // namespace cmp::spheres
