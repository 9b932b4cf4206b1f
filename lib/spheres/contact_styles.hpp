#pragma once
// The contact styles of soft spheres in a periodic box, one table (core/registry.hpp): each
// builds a force field (forcefield/force_field.hpp) over the flat positions (x0, y0, z0, x1,
// ...). `hertz` is HertzSpheres, the law of the thesis's Chapter 5.
#include "forcefield/force_field.hpp"
#include "forcefield/hertz.hpp"

#include <Eigen/Core>

#include <memory>
#include <span>
#include <string>

namespace cmp::spheres {

struct ContactStyle {
  const char* name;
  const char* description;
  // Throws cmp::UsageError for a bad box, radii or material.
  std::unique_ptr<ForceField> (*make)(const Eigen::Vector3d& box, const Eigen::VectorXd& radii,
                                      const HertzMaterial& material);
};

std::span<const ContactStyle> contact_styles();
// Throws cmp::UsageError "unknown sphere contact model 'x' (known: ...)".
const ContactStyle& contact_style(const std::string& name);

}  // namespace cmp::spheres
