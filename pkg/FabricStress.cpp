#include "FabricStress.hpp"

#include <cmath>
#include <string>

#include "InputCheck.hpp"

namespace ballast {

namespace {
	double volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

	// A subnormal volume has lost precision and a zero one gives 0/0: both are refused, like an infinite one.
	[[noreturn]] void badVolume(const std::string& name, double r)
	{
		throw ArgumentError(name + ": expected a radius whose volume 4/3 pi r^3 neither under- nor overflows "
		                    + "(about 2e-103 < r < 3e102), got " + formatValue(r));
	}
}  // namespace

double sphereVolume(double r)
{
	requirePositive("radius", r);
	const double V = volume(r);
	if (!std::isnormal(V)) badVolume("radius", r);
	return V;
}

double sphereVolume(const char* array, long index, double r)
{
	requirePositive(array, index, r);
	const double V = volume(r);
	if (!std::isnormal(V)) badVolume(std::string(array) + "[" + std::to_string(index) + "]", r);
	return V;
}

Mat3 fabricStress(double r, const std::vector<Vec3>& branches, const std::vector<Vec3>& forces)
{
	if (branches.size() != forces.size())
		throw ArgumentError("forces: expected as many forces as branches (" + std::to_string(branches.size()) + "), got "
		                    + std::to_string(forces.size()));
	const double V = sphereVolume(r);
	Mat3         s = Mat3::Zero();
	for (size_t c = 0; c < branches.size(); ++c)
		s += branches[c] * forces[c].transpose();  // l_i F_j
	return s / V;
}

void fabricStressMany(int nGrains, const double* radii, int nContacts, const long* grainOf, const double* branches,
                      const double* forces, double* out)
{
	if (nGrains < 0) throw ArgumentError("nGrains: expected >= 0, got " + std::to_string(nGrains));
	std::vector<double> V(nGrains);
	for (int g = 0; g < nGrains; ++g)
		V[g] = sphereVolume("radii", g, radii[g]);
	for (int c = 0; c < nContacts; ++c)
		if (grainOf[c] < 0 || grainOf[c] >= nGrains)
			throw ArgumentError("grainIndex[" + std::to_string(c) + "]: expected 0 <= index < " + std::to_string(nGrains)
			                    + ", got " + std::to_string(grainOf[c]));
	Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor>> S(out, nGrains, 9);
	S.setZero();
	for (int c = 0; c < nContacts; ++c) {
		const double* l = branches + 3 * c;
		const double* f = forces + 3 * c;
		double*       s = out + 9 * grainOf[c];
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				s[3 * i + j] += l[i] * f[j];
	}
	for (int g = 0; g < nGrains; ++g)
		S.row(g) /= V[g];
}

}  // namespace ballast
