// Replacement of a crushed grain by smaller spheres, Dubina & Elias section 2 and Fig. 1.
// Every fragment lies fully inside the parent sphere and no two fragments overlap; within each
// layout the radii are the largest these constraints allow. Volume kept (fraction of the parent):
//   tetra4  four equal spheres on a regular tetrahedron       0.3633 (63.7 % lost)
//   planar4 four equal spheres on a square in one plane       0.2843 (71.6 % lost, the paper's "about 70 %")
//   octa6   six equal spheres on the octahedron axes          0.4264 (57.4 % lost, as in the paper)
//   fill14  octa6 plus eight spheres in the corner gaps       0.5239 (47.6 % lost; the paper: "more than 28 %")
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "Types.hpp"

namespace ballast {

enum class Layout { Tetra4, Planar4, Octa6, Fill14 };

// 4 -> tetra4, 6 -> octa6, 14 -> fill14; anything else throws ArgumentError naming "pattern".
Layout layoutFromCount(long n);
// "tetra4", "planar4", "octa6", "fill14" (or "4", "6", "14"); anything else throws.
Layout layoutFromName(const std::string& name);
std::string layoutName(Layout layout);

// Fragments of a parent of unit radius centred at the origin, as [x, y, z, r].
std::vector<Sphere4> fragmentPattern(Layout layout);

// Sum of fragment volumes over the parent volume [-].
double keptVolumeFraction(Layout layout);

// A uniformly distributed rotation, reproducible: the same (seed, counter) gives the same matrix
// on every platform (own integer generator, no std:: distributions).
Mat3 randomRotation(std::uint64_t seed, std::uint64_t counter);

// Fragments of a parent of radius r [m] at centre c, rotated by rot: [x, y, z, r] in metres.
std::vector<Sphere4> placeFragments(Layout layout, const Vec3& centre, double r, const Mat3& rot);

}  // namespace ballast
