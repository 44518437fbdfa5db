// The flexible membrane of a cylindrical triaxial specimen, as a stress boundary on its outermost grains
// (docs/triaxial.md, "The membrane"). A latex membrane under a cell pressure p rests on the grains it touches and
// bridges the gaps between them; it carries no shear and no axial load.
//
// The lateral surface between the platens (z0 < z < z1) is cut into nTheta x nZ cells, dtheta = 2 pi / nTheta,
// dz = (z1 - z0) / nZ. Through each cell's centre (theta_c, z_c) a ray comes in radially from outside; the first
// grain surface it meets is where the membrane rests there: for a sphere of centre C and radius r, with
// u = (cos theta_c, sin theta_c, 0) and w = (-sin theta_c, cos theta_c, 0),
//     rho_hit = C.u + sqrt(r^2 - (C.w)^2 - (z_c - C_z)^2)          (when the root is real),
// the largest over the grains. The membrane does not follow a ray deep into a gap: a cell whose hit lies more than
// `depth` inside the outermost hit of its 3 x 3 neighbourhood (or that no ray reaches) is bridged, the membrane
// there at that neighbourhood's outermost radius less `depth`, its load carried by the grain of that outermost hit.
// Each cell passes the pressure on its area at the membrane's radius to its grain, as a horizontal force towards
// the axis through the grain's centre (a frictionless membrane pushes along the grain's normal):
//     F = p rho_m dtheta dz (-u)
// so the radial forces add up to p times the membrane's lateral area. The membrane encloses
//     V = sum over cells of rho_m^2 / 2 dtheta dz.
#pragma once
#include <vector>

namespace ballast {

struct MembraneGrid {
	double axisX, axisY;  // the specimen's axis [m] (vertical)
	double z0, z1;        // the platens' faces [m], z0 < z1
	long   nTheta, nZ;    // cells around and along, each >= 3 and >= 1
	double depth;         // [m] >= 0: how far into a gap the membrane follows a ray

	// The grid checked (ArgumentError naming the first bad field).
	static MembraneGrid checked(double axisX, double axisY, double z0, double z1, long nTheta, long nZ, double depth);
};

struct MembraneLoad {
	std::vector<double> force;   // (n, 3) [N]: each grain's share of the pressure, 0 for grains the membrane misses
	std::vector<double> radius;  // (nZ, nTheta) [m]: the membrane's radius at each cell, rho_m
	std::vector<long>   owner;   // (nZ, nTheta): the grain index carrying each cell, -1 if no grain at all
	long   bridged = 0;          // cells where the membrane bridges a gap
	long   empty   = 0;          // cells with no grain in their neighbourhood (carrying nothing)
	double area    = 0;          // [m^2] the membrane's lateral area, sum of rho_m dtheta dz over cells carried
	double volume  = 0;          // [m^3] what it encloses between the platens (empty cells at their row's mean radius)
};

// The membrane's load for n grains (centres (n, 3) [m] row-major, radii (n) [m] > 0) under the pressure p [Pa] >= 0.
MembraneLoad membraneLoad(const MembraneGrid& grid, long n, const double* centres, const double* radii, double pressure);

}  // namespace ballast
