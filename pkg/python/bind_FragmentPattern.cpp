// Binding of FragmentPattern.hpp: the fragment layouts of Fig. 1, their random orientation and placement.
#include <cstdint>
#include <string>
#include <vector>

#include "../FragmentPattern.hpp"
#include "../InputCheck.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	// A pattern: a name ('octa6', '6') or a Python or NumPy integer (4, 6, 14).
	Layout asLayout(const bp::object& pattern)
	{
		const std::string        expected = "4, 6, 14 or one of 'tetra4', 'planar4', 'octa6', 'fill14'";
		bp::extract<std::string> asStr(pattern);
		if (asStr.check()) return layoutFromName(asStr());
		const bp::object n        = asInteger(pattern, "pattern", expected);
		int              overflow = 0;
		const long       v        = PyLong_AsLongAndOverflow(n.ptr(), &overflow);
		if (overflow) throw ArgumentError("pattern: expected " + expected + ", got " + pyStr(n));
		return layoutFromCount(v);
	}

	np::ndarray spheresToArray(const std::vector<Sphere4>& v)
	{
		np::ndarray out = emptyDoubles({(long)v.size(), 4});
		for (size_t i = 0; i < v.size(); ++i)
			for (int k = 0; k < 4; ++k)
				wptr(out)[4 * i + k] = v[i][k];
		return out;
	}

	np::ndarray matrixToArray(const Mat3& m)
	{
		np::ndarray out = emptyDoubles({3, 3});
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				wptr(out)[3 * i + j] = m(i, j);
		return out;
	}

	np::ndarray fragmentPatternOf(const bp::object& pattern) { return spheresToArray(fragmentPattern(asLayout(pattern))); }
	double      keptVolumeFractionOf(const bp::object& pattern) { return keptVolumeFraction(asLayout(pattern)); }
	std::string patternName(const bp::object& pattern) { return layoutName(asLayout(pattern)); }

	np::ndarray randomRotationOf(const bp::object& seed, const bp::object& counter)
	{
		return matrixToArray(randomRotation(asSeed(seed), asCounter(counter, "counter")));
	}

	np::ndarray placeFragmentsOf(const bp::object& pattern, const bp::object& centre, const bp::object& radius,
	                             const bp::object& seed, const bp::object& counter)
	{
		const Layout layout = asLayout(pattern);
		np::ndarray  c      = asDoubles(centre, "centre");
		requireShape(c, "centre", {3}, "a 3-vector");
		const double r   = asScalar(radius, "radius");  // placeFragments checks r > 0
		const Mat3   rot = randomRotation(asSeed(seed), asCounter(counter, "counter"));
		return finiteResult(spheresToArray(placeFragments(layout, Vec3(dptr(c)[0], dptr(c)[1], dptr(c)[2]), r, rot)),
		                    "centre, radius", "fragment position");
	}
}  // namespace

void registerFragmentPattern()
{
	bp::def("fragmentPattern", fragmentPatternOf, (bp::arg("pattern")),
	        "Fragments of a unit parent at the origin as an (n,4) array [x,y,z,r]: pattern 4 (tetra4), 6 (octa6),\n"
	        "14 (fill14), or the names 'tetra4', 'planar4', 'octa6', 'fill14'.");
	bp::def("keptVolumeFraction", keptVolumeFractionOf, (bp::arg("pattern")), "Fragment volume / parent volume [-].");
	bp::def("patternName", patternName, (bp::arg("pattern")), "Canonical name of a pattern ('tetra4', ...).");
	bp::def("randomRotation", randomRotationOf, (bp::arg("seed"), "counter"),
	        "Uniform random rotation matrix (3,3), the same for the same (seed, counter) on every platform.");
	bp::def("placeFragments", placeFragmentsOf, (bp::arg("pattern"), "centre", "radius", "seed", "counter"),
	        "Fragments of a parent of the given radius [m] and centre [m], randomly rotated by (seed, counter): (n,4).");
}

}  // namespace binding
}  // namespace ballast
