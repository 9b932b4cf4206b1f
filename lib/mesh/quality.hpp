#pragma once
// Mesh quality metrics of thesis A.3.1, on flat triangles.
#include "mesh/tri_mesh.hpp"
#include <Eigen/Core>

namespace cmp::mesh {

struct MeshQuality {
  double q_area = 0;          // Eq. A.2: min_i C_i / max_i C_i over vertex dual areas (1 is best)
  double q_angle = 0;         // Eq. A.3: smallest angle in the mesh / (pi/3) (1: all equilateral)
  double q_radius_ratio = 0;  // Eq. A.4: min over triangles of 2 r_in / r_out (1: equilateral)
  double dual_area_min = 0, dual_area_max = 0;
  double angle_min = 0, angle_max = 0;  // radians, over all triangle corners
  double radius_ratio_mean = 0;         // mean of 2 r_in / r_out (a distribution summary)
  double low_quality_fraction = 0;      // fraction of triangles with 2 r_in / r_out < 0.5 (the rule of thumb of A.4.2)
};

// All of MeshQuality in one O(#V + #F) pass. Vertices in no triangle are ignored in q_area.
//   V  #V by 3, F  #F by 3 (F non-empty)
MeshQuality mesh_quality(const VertexMatrix& V, const FaceMatrix& F);

// 2 r_in / r_out = (b+c-a)(c+a-b)(a+b-c) / (abc) of every triangle (Eq. A.4), in [0, 1].
Eigen::VectorXd face_radius_ratios(const VertexMatrix& V, const FaceMatrix& F);

// The three corner angles of every triangle (radians), #F by 3, column k at vertex F(f,k).
Eigen::MatrixX3d face_angles(const VertexMatrix& V, const FaceMatrix& F);

}  // namespace cmp::mesh
