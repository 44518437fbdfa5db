#include "FragmentPattern.hpp"

#include <cmath>

#include "InputCheck.hpp"
#include "Random.hpp"

namespace ballast {

Layout layoutFromCount(long n)
{
	switch (n) {
		case 4: return Layout::Tetra4;
		case 6: return Layout::Octa6;
		case 14: return Layout::Fill14;
		default:
			throw ArgumentError("pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got "
			                    + std::to_string(n));
	}
}

Layout layoutFromName(const std::string& name)
{
	if (name == "tetra4" || name == "4") return Layout::Tetra4;
	if (name == "planar4") return Layout::Planar4;
	if (name == "octa6" || name == "6") return Layout::Octa6;
	if (name == "fill14" || name == "14") return Layout::Fill14;
	throw ArgumentError("pattern: expected 4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14', got '" + name + "'");
}

std::string layoutName(Layout layout)
{
	switch (layout) {
		case Layout::Tetra4: return "tetra4";
		case Layout::Planar4: return "planar4";
		case Layout::Octa6: return "octa6";
		case Layout::Fill14: return "fill14";
	}
	return "?";
}

namespace {
	// n spheres of radius rho touching the unit shell with centres at distance d = 1 - rho along dirs.
	void addShell(std::vector<Sphere4>& out, const std::vector<Vec3>& dirs, double rho)
	{
		for (const Vec3& u : dirs) {
			const Vec3 c = (1.0 - rho) * u.normalized();
			out.emplace_back(c.x(), c.y(), c.z(), rho);
		}
	}

	std::vector<Vec3> octaDirs()
	{
		return {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
	}

	std::vector<Vec3> cubeCornerDirs()
	{
		std::vector<Vec3> d;
		for (int sx : {-1, 1})
			for (int sy : {-1, 1})
				for (int sz : {-1, 1})
					d.emplace_back(sx, sy, sz);
		return d;
	}
}  // namespace

std::vector<Sphere4> fragmentPattern(Layout layout)
{
	std::vector<Sphere4> out;
	switch (layout) {
		case Layout::Tetra4: {
			// neighbours touch: edge 2 rho = d sqrt(8/3) with d = 1 - rho
			const double k = std::sqrt(2.0 / 3.0);
			addShell(out, {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)}, k / (1.0 + k));
			break;
		}
		case Layout::Planar4:
			// square: edge 2 rho = d sqrt(2)
			addShell(out, {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)}, 1.0 / (1.0 + std::sqrt(2.0)));
			break;
		case Layout::Octa6: addShell(out, octaDirs(), 1.0 / (1.0 + std::sqrt(2.0))); break;
		case Layout::Fill14: {
			// Octahedral spheres at full size, then corner spheres along the cube diagonals touching the
			// shell (e = 1 - s) and the three nearest octahedral spheres:
			//   e^2 - 2 e d / sqrt(3) + d^2 = (rho + s)^2  ->  linear in e.
			// Shrinking the octahedral spheres to enlarge the corner ones keeps less volume (checked
			// numerically over the whole family), so this is the optimum of the symmetric layout.
			const double rho = 1.0 / (1.0 + std::sqrt(2.0)), d = 1.0 - rho;
			const double e   = ((1.0 + rho) * (1.0 + rho) - d * d) / (2.0 * (1.0 + rho) - 2.0 * d / std::sqrt(3.0));
			addShell(out, octaDirs(), rho);
			addShell(out, cubeCornerDirs(), 1.0 - e);
			break;
		}
	}
	return out;
}

double keptVolumeFraction(Layout layout)
{
	double v = 0;
	for (const Sphere4& s : fragmentPattern(layout))
		v += s[3] * s[3] * s[3];
	return v;
}

Mat3 randomRotation(std::uint64_t seed, std::uint64_t counter)
{
	KeyedRandom rng(seed, counter);
	// Shoemake's uniform random unit quaternion from three uniforms.
	const double u1 = rng.uniform01(), u2 = rng.uniform01(), u3 = rng.uniform01();
	const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
	Eigen::Quaterniond q(b * std::cos(2 * M_PI * u3), a * std::sin(2 * M_PI * u2), a * std::cos(2 * M_PI * u2),
	                     b * std::sin(2 * M_PI * u3));
	return q.normalized().toRotationMatrix();
}

std::vector<Sphere4> placeFragments(Layout layout, const Vec3& centre, double r, const Mat3& rot)
{
	requirePositive("radius", r);
	for (int i = 0; i < 3; ++i)
		requireFinite("centre[" + std::to_string(i) + "]", centre[i]);
	std::vector<Sphere4> out = fragmentPattern(layout);
	for (Sphere4& s : out) {
		const Vec3 c = centre + r * (rot * s.head<3>());
		s << c, r * s[3];
	}
	return out;
}

}  // namespace ballast
