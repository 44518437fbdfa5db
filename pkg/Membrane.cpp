#include "Membrane.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "InputCheck.hpp"

namespace ballast {

MembraneGrid MembraneGrid::checked(double axisX, double axisY, double z0, double z1, long nTheta, long nZ, double depth)
{
	requireFinite("axisX", axisX);
	requireFinite("axisY", axisY);
	requireFinite("z0", z0);
	requireFinite("z1", z1);
	if (!(z1 > z0)) throw ArgumentError("z1: expected above z0 = " + formatValue(z0) + ", got " + formatValue(z1));
	if (nTheta < 3) throw ArgumentError("nTheta: expected at least 3 cells around, got " + std::to_string(nTheta));
	if (nZ < 1) throw ArgumentError("nZ: expected at least 1 cell along, got " + std::to_string(nZ));
	if (nTheta * nZ > 100000000L)
		throw ArgumentError("nTheta, nZ: expected at most 1e8 cells, got " + std::to_string(nTheta) + " x " + std::to_string(nZ));
	requireNonNegative("depth", depth);
	return MembraneGrid{axisX, axisY, z0, z1, nTheta, nZ, depth};
}

MembraneLoad membraneLoad(const MembraneGrid& g, long n, const double* centres, const double* radii, double pressure)
{
	requireNonNegative("pressure", pressure);
	const double dth = 2 * M_PI / g.nTheta, dz = (g.z1 - g.z0) / g.nZ;
	const long   cells = g.nTheta * g.nZ;
	std::vector<double> cosC(g.nTheta), sinC(g.nTheta);  // each column's ray direction, (k + 1/2) dth, once
	for (long k = 0; k < g.nTheta; ++k) {
		cosC[k] = std::cos((k + 0.5) * dth);
		sinC[k] = std::sin((k + 0.5) * dth);
	}
	std::vector<double> hit(cells, -INFINITY);  // the outermost hit of each cell's own ray [m]
	std::vector<long>   own(cells, -1);
	for (long i = 0; i < n; ++i) {
		const double r = radii[i];
		requirePositive("radii", i, r);
		const double x = centres[3 * i] - g.axisX, y = centres[3 * i + 1] - g.axisY, z = centres[3 * i + 2];
		requireFinite("centres", 3 * i, x);
		requireFinite("centres", 3 * i + 1, y);
		requireFinite("centres", 3 * i + 2, z);
		// the cells whose centre's ray can meet this sphere: z_c within r of its centre, theta_c within its silhouette
		// clamped as doubles before the cast: far-off or huge grains give infinities (NaN fails the test too)
		const double zLo = std::ceil((z - r - g.z0) / dz - 0.5), zHi = std::floor((z + r - g.z0) / dz - 0.5);
		if (!(zLo <= zHi && zHi >= 0 && zLo <= g.nZ - 1)) continue;
		const long kz0 = static_cast<long>(std::max(0.0, zLo));
		const long kz1 = static_cast<long>(std::min(static_cast<double>(g.nZ - 1), zHi));
		const double rc = std::hypot(x, y);
		long         kt0 = 0, kt1 = g.nTheta - 1;  // a sphere around the axis: every direction
		if (rc > r) {
			const double th = std::atan2(y, x), half = std::asin(r / rc);
			kt0 = static_cast<long>(std::ceil((th - half) / dth - 0.5));
			kt1 = static_cast<long>(std::floor((th + half) / dth - 0.5));
		}
		for (long kt = kt0; kt <= kt1; ++kt) {
			const long   k  = ((kt % g.nTheta) + g.nTheta) % g.nTheta;
			const double c = cosC[k], s = sinC[k];
			const double a = x * c + y * s, b = -x * s + y * c;
			for (long kz = kz0; kz <= kz1; ++kz) {
				const double h = g.z0 + (kz + 0.5) * dz - z, disc = r * r - b * b - h * h;
				if (disc < 0) continue;
				const double rho = a + std::sqrt(disc);
				const long   cell = kz * g.nTheta + k;
				if (rho > hit[cell]) {
					hit[cell] = rho;
					own[cell] = i;
				}
			}
		}
	}
	MembraneLoad out;
	out.force.assign(3 * n, 0.0);
	out.radius.assign(cells, 0.0);
	out.owner.assign(cells, -1);
	for (long kz = 0; kz < g.nZ; ++kz) {
		double rowSum = 0;
		long   rowCarried = 0;
		for (long k = 0; k < g.nTheta; ++k) {
			const long cell = kz * g.nTheta + k;
			double     top  = -INFINITY;  // the outermost hit of the 3 x 3 neighbourhood and its grain
			long       topOwner = -1;
			for (long jz = std::max(0L, kz - 1); jz <= std::min(g.nZ - 1, kz + 1); ++jz)
				for (long jt = k - 1; jt <= k + 1; ++jt) {
					const long other = jz * g.nTheta + ((jt + g.nTheta) % g.nTheta);
					if (own[other] >= 0 && hit[other] > top) {
						top      = hit[other];
						topOwner = own[other];
					}
				}
			if (topOwner < 0) {
				++out.empty;
				continue;
			}
			double rho = hit[cell];
			long   by  = own[cell];
			const bool gap = by < 0 || rho < top - g.depth;  // the membrane spans it, resting on the outermost grain near
			if (gap) {
				rho = top - g.depth;
				by  = topOwner;
			}
			if (rho <= 0) {   // a neighbourhood reaching no further than depth from the axis: nothing to press on
				++out.empty;
				continue;
			}
			out.bridged += gap;
			const double f = pressure * rho * dth * dz;
			out.force[3 * by] -= f * cosC[k];
			out.force[3 * by + 1] -= f * sinC[k];
			out.radius[cell] = rho;
			out.owner[cell]  = by;
			out.area += rho * dth * dz;
			rowSum += rho;
			++rowCarried;
		}
		const double rowMean = rowCarried ? rowSum / rowCarried : 0.0;
		for (long k = 0; k < g.nTheta; ++k) {
			const double rho = out.owner[kz * g.nTheta + k] >= 0 ? out.radius[kz * g.nTheta + k] : rowMean;
			out.volume += 0.5 * rho * rho * dth * dz;
		}
	}
	// radii or centres too large for doubles (or a pressure that overflows them) give no load to trust
	requireFiniteResult("centres, radii, pressure", "membrane load", pressure * out.area);
	requireFiniteResult("centres, radii", "enclosed volume", out.volume);
	return out;
}

}  // namespace ballast
