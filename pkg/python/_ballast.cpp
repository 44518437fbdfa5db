// Python binding `ballast._ballast` of the C++ core (Boost.Python + Boost.Python NumPy).
// Arrays in, arrays out: every loop over grains or contacts runs here, never in Python.
// Bad input raises TypeError (wrong type, dtype or shape) or ValueError (bad value, or a result that would
// not be finite) naming the argument. NumPy scalars and 0-d arrays are taken wherever Python numbers are.
#include <boost/python.hpp>
#include <boost/python/numpy.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "../BallastAbrasionEngine.hpp"
#include "../BallastCrushEngine.hpp"
#include "../FabricStress.hpp"
#include "../Fatigue.hpp"
#include "../Weibull.hpp"
#include "../FragmentPattern.hpp"
#include "../HertzPressure.hpp"
#include "../InputCheck.hpp"
#include "../Strength.hpp"
#include "../VonMises.hpp"

namespace bp = boost::python;
namespace np = boost::python::numpy;
using namespace ballast;

namespace {

struct TypeError : std::runtime_error {
	explicit TypeError(const std::string& w) : std::runtime_error(w) {}
};

std::string pyStr(const bp::object& o) { return bp::extract<std::string>(bp::str(o)); }

std::string shapeOf(const np::ndarray& a)
{
	std::string s = "(";
	for (int i = 0; i < a.get_nd(); ++i)
		s += std::to_string(a.shape(i)) + (a.get_nd() == 1 || i + 1 < a.get_nd() ? "," : "");
	return s + ")";
}

long sizeOf(const np::ndarray& a) { return bp::len(a.attr("ravel")()); }

// Converts obj to a C-contiguous array of dtype (float64 or int64), accepting only the dtype kinds given.
np::ndarray asArray(const bp::object& obj, const std::string& name, const char* kinds, const np::dtype& dt)
{
	bp::object numpy = bp::import("numpy");
	bp::object arr;
	try {
		arr = numpy.attr("asarray")(obj);
	} catch (const bp::error_already_set&) {
		PyErr_Clear();
		throw TypeError(name + ": expected an array of numbers, got " + pyStr(obj.attr("__class__").attr("__name__")));
	}
	const std::string kind = bp::extract<std::string>(arr.attr("dtype").attr("kind"));
	if (kind.size() != 1 || std::string(kinds).find(kind[0]) == std::string::npos)
		throw TypeError(name + ": expected " + (std::string(kinds) == "iu" ? "integers" : "real numbers") + ", got dtype "
		                + pyStr(arr.attr("dtype")));
	if (kind == "u" && dt == np::dtype::get_builtin<long>()) {  // uint64 above 2^63 - 1 would wrap round to negative
		np::ndarray u = bp::extract<np::ndarray>(numpy.attr("require")(arr, np::dtype::get_builtin<std::uint64_t>(), "C"));
		const auto* p = reinterpret_cast<const std::uint64_t*>(u.get_data());
		for (long i = 0, n = sizeOf(u); i < n; ++i)
			if (p[i] > (std::uint64_t)std::numeric_limits<long>::max())
				throw ArgumentError(name + ": expected integers below 2^63, got " + std::to_string(p[i]) + " at flat index "
				                    + std::to_string(i));
	}
	bp::object c = numpy.attr("require")(arr, dt, "C");  // ascontiguousarray would turn 0-d into 1-d
	return bp::extract<np::ndarray>(c);
}

np::ndarray asDoubles(const bp::object& obj, const std::string& name)
{
	np::ndarray a = asArray(obj, name, "iuf", np::dtype::get_builtin<double>());
	const long  n = sizeOf(a);
	const auto* p = reinterpret_cast<const double*>(a.get_data());
	for (long i = 0; i < n; ++i)
		if (!std::isfinite(p[i]))
			throw ArgumentError(name + ": expected finite numbers, got " + formatValue(p[i]) + " at flat index " + std::to_string(i));
	return a;
}

np::ndarray asIndices(const bp::object& obj, const std::string& name)
{
	return asArray(obj, name, "iu", np::dtype::get_builtin<long>());
}

// Checks the shape; -1 in want is any length. Returns the first dimension.
long requireShape(const np::ndarray& a, const std::string& name, const std::vector<long>& want, const std::string& what)
{
	bool ok = a.get_nd() == (int)want.size();
	for (int i = 0; ok && i < a.get_nd(); ++i)
		ok = want[i] < 0 || a.shape(i) == want[i];
	if (!ok) throw TypeError(name + ": expected " + what + ", got shape " + shapeOf(a));
	return want.empty() ? 1 : a.shape(0);
}

const double* dptr(const np::ndarray& a) { return reinterpret_cast<const double*>(a.get_data()); }
const long*   lptr(const np::ndarray& a) { return reinterpret_cast<const long*>(a.get_data()); }

np::ndarray emptyDoubles(std::vector<long> shape)
{
	std::vector<Py_intptr_t> s(shape.begin(), shape.end());
	return np::zeros(s.size(), s.data(), np::dtype::get_builtin<double>());
}
double* wptr(np::ndarray& a) { return reinterpret_cast<double*>(a.get_data()); }

// A real number: Python int or float, NumPy integer or float scalar, or 0-d array.
double asScalar(const bp::object& obj, const std::string& name)
{
	np::ndarray a = asArray(obj, name, "iuf", np::dtype::get_builtin<double>());
	if (a.get_nd() != 0) throw TypeError(name + ": expected a number, got an array of shape " + shapeOf(a));
	requireFinite(name, *dptr(a));
	return *dptr(a);
}

// An integer: Python int, NumPy integer scalar or 0-d integer array, as a Python int. Bools are refused
// (NumPy still lets np.bool_ pass as an index), and so are floats, even 6.0.
bp::object asInteger(const bp::object& obj, const std::string& name, const std::string& what)
{
	const bp::object npBool = bp::import("numpy").attr("bool_");
	const bool       isBool = PyBool_Check(obj.ptr()) || PyObject_IsInstance(obj.ptr(), npBool.ptr()) == 1;
	PyObject*        i      = isBool ? nullptr : PyNumber_Index(obj.ptr());
	if (!i) {
		PyErr_Clear();
		throw TypeError(name + ": expected " + what + ", got " + pyStr(obj.attr("__repr__")()));
	}
	return bp::object(bp::handle<>(i));
}

// Refuses a result that is not finite (an overflow, or a division by an underflowed number), naming the
// arguments it is computed from; the error gives the first index of the result (a grain, a contact)
// unless the result is one value or one tensor (indexed false).
const np::ndarray& finiteResult(const np::ndarray& out, const char* names, const char* what, bool indexed = true)
{
	const long n = sizeOf(out);
	if (out.get_nd() == 0 || !indexed) {
		for (long k = 0; k < n; ++k)
			requireFiniteResult(names, what, dptr(out)[k]);
		return out;
	}
	const long perRow = out.shape(0) ? n / out.shape(0) : 1;
	for (long k = 0; k < n; ++k)
		requireFiniteResult(names, what, k / perRow, dptr(out)[k]);
	return out;
}

// ---------------------------------------------------------------- eq. 3
np::ndarray py_fabricStress(const bp::object& radius, const bp::object& branches, const bp::object& forces)
{
	const double r = asScalar(radius, "radius");
	sphereVolume(r);  // r > 0 and a volume that neither under- nor overflows; errors name radius, not radii[0]
	np::ndarray  l  = asDoubles(branches, "branches");
	np::ndarray  f  = asDoubles(forces, "forces");
	const long   nl = requireShape(l, "branches", {-1, 3}, "an (n,3) array");
	const long   nf = requireShape(f, "forces", {-1, 3}, "an (n,3) array");
	if (nl != nf) throw TypeError("forces: expected as many rows as branches (" + std::to_string(nl) + "), got " + std::to_string(nf));
	std::vector<long> zero(nl, 0);
	np::ndarray       out = emptyDoubles({3, 3});
	fabricStressMany(1, &r, nl, zero.data(), dptr(l), dptr(f), wptr(out));
	return finiteResult(out, "radius, branches, forces", "fabric stress", false);
}

np::ndarray py_grainStresses(const bp::object& radii, const bp::object& grainIndex, const bp::object& branches, const bp::object& forces)
{
	np::ndarray r  = asDoubles(radii, "radii");
	const long  n  = requireShape(r, "radii", {-1}, "a 1-d array");
	np::ndarray gi = asIndices(grainIndex, "grainIndex");
	const long  m  = requireShape(gi, "grainIndex", {-1}, "a 1-d array");
	np::ndarray l  = asDoubles(branches, "branches");
	np::ndarray f  = asDoubles(forces, "forces");
	requireShape(l, "branches", {m, 3}, "an (" + std::to_string(m) + ",3) array, one row per grainIndex");
	requireShape(f, "forces", {m, 3}, "an (" + std::to_string(m) + ",3) array, one row per grainIndex");
	np::ndarray out = emptyDoubles({n, 3, 3});
	fabricStressMany(n, dptr(r), m, lptr(gi), dptr(l), dptr(f), wptr(out));
	return finiteResult(out, "radii, branches, forces", "fabric stress");
}

// ---------------------------------------------------------------- eq. 2
bp::object py_vonMises(const bp::object& sigma)
{
	np::ndarray s = asDoubles(sigma, "sigma");
	if (s.get_nd() == 2) {
		requireShape(s, "sigma", {3, 3}, "a (3,3) or (N,3,3) array");
		const double v = vonMises(Eigen::Map<const Mat3>(dptr(s)));
		requireFiniteResult("sigma", "von Mises stress", v);
		return bp::object(v);
	}
	const long  n   = requireShape(s, "sigma", {-1, 3, 3}, "a (3,3) or (N,3,3) array");
	np::ndarray out = emptyDoubles({n});
	for (long i = 0; i < n; ++i)
		wptr(out)[i] = vonMises(Eigen::Map<const Mat3>(dptr(s) + 9 * i));
	return finiteResult(out, "sigma", "von Mises stress");
}

np::ndarray py_principalStresses(const bp::object& sigma)
{
	np::ndarray s = asDoubles(sigma, "sigma");
	const bool  one = s.get_nd() == 2;
	const long  n   = one ? (requireShape(s, "sigma", {3, 3}, "a (3,3) or (N,3,3) array"), 1L)
	                      : requireShape(s, "sigma", {-1, 3, 3}, "a (3,3) or (N,3,3) array");
	np::ndarray out = one ? emptyDoubles({3}) : emptyDoubles({n, 3});
	for (long i = 0; i < n; ++i) {
		// row-major storage read as column-major is the transpose: same symmetric part
		const Vec3 p = principalStresses(Eigen::Map<const Mat3>(dptr(s) + 9 * i));
		for (int k = 0; k < 3; ++k)
			wptr(out)[3 * i + k] = p[k];
	}
	return finiteResult(out, "sigma", "principal stress", !one);
}

// ---------------------------------------------------------------- eq. 4, eq. 7: scalars or arrays
// Broadcasts the arguments like NumPy; returns a float when all are scalars. what names the result.
bp::object elementwise(const std::vector<std::pair<std::string, bp::object>>& args, const char* what, double (*fn)(const double*))
{
	std::vector<np::ndarray> a;
	bool                     allScalar = true;
	bp::list                 objs;
	std::string              names;
	for (const auto& kv : args) {
		a.push_back(asDoubles(kv.second, kv.first));
		allScalar = allScalar && a.back().get_nd() == 0;
		objs.append(a.back());
		names += (names.empty() ? "" : ", ") + kv.first;
	}
	bp::object numpy = bp::import("numpy");
	bp::object b;
	try {
		b = numpy.attr("broadcast_arrays")(*bp::tuple(objs));
	} catch (const bp::error_already_set&) {
		PyErr_Clear();
		std::string shapes;
		for (size_t i = 0; i < a.size(); ++i)
			shapes += (i ? ", " : "") + shapeOf(a[i]);
		throw TypeError(names + ": expected scalars or arrays of equal length, got shapes " + shapes);
	}
	std::vector<np::ndarray> c;
	for (size_t i = 0; i < a.size(); ++i)
		c.push_back(bp::extract<np::ndarray>(numpy.attr("ascontiguousarray")(bp::object(b[i]), "float64")));
	const long n = sizeOf(c[0]);
	np::ndarray out = bp::extract<np::ndarray>(numpy.attr("zeros")(bp::object(c[0].attr("shape")), "float64"));
	std::vector<double> x(a.size());
	for (long k = 0; k < n; ++k) {
		for (size_t i = 0; i < c.size(); ++i)
			x[i] = dptr(c[i])[k];
		wptr(out)[k] = fn(x.data());
	}
	finiteResult(out, names.c_str(), what);
	if (allScalar) return bp::object(wptr(out)[0]);
	return out;
}

bp::object py_hertzPressure(const bp::object& Fn, const bp::object& R1, const bp::object& R2, const bp::object& uN)
{
	return elementwise({{"Fn", Fn}, {"R1", R1}, {"R2", R2}, {"uN", uN}}, "Hertz pressure",
	                   [](const double* x) { return hertzPressure(x[0], x[1], x[2], x[3]); });
}

bp::object py_effectiveRadius(const bp::object& R1, const bp::object& R2)
{
	return elementwise({{"R1", R1}, {"R2", R2}}, "effective radius", [](const double* x) { return effectiveRadius(x[0], x[1]); });
}

bp::object py_sizeStrength(const bp::object& ft0, const bp::object& r, const bp::object& m)
{
	return elementwise({{"ft0", ft0}, {"radius", r}, {"m", m}}, "strength ft0 / r^m",
	                   [](const double* x) { return sizeStrength(x[0], x[1], x[2]); });
}

// ---------------------------------------------------------------- snapshot decisions
bp::tuple py_crushCheck(const bp::object& stresses, const bp::object& radii, const bp::object& ft0, const bp::object& m,
                        const bp::object& rMin, const std::string& criterion, const bp::object& fMax, const bp::object& factor)
{
	CrushParameters p{asScalar(ft0, "ft0"), asScalar(m, "m"), asScalar(rMin, "rMin"), parseCriterion(criterion)};
	p.validate();
	np::ndarray s = asDoubles(stresses, "stresses");
	np::ndarray r = asDoubles(radii, "radii");
	const long  n = requireShape(r, "radii", {-1}, "a 1-d array");
	requireShape(s, "stresses", {n, 3, 3}, "an (" + std::to_string(n) + ",3,3) array, one tensor per radius");
	// optional per-grain arrays: None, or one value per radius
	auto perGrain = [&](const bp::object& o, const char* name) -> std::vector<double> {
		if (o.is_none()) return {};
		np::ndarray a = asDoubles(o, name);
		requireShape(a, name, {n}, "None or an (" + std::to_string(n) + ",) array, one value per radius");
		return std::vector<double>(dptr(a), dptr(a) + n);
	};
	const std::vector<double> fm = perGrain(fMax, "fMax"), w = perGrain(factor, "factor");
	np::ndarray               stress = emptyDoubles({n}), ft = emptyDoubles({n});
	std::vector<std::uint8_t> crush(n);
	evaluateCrushing(p, n, dptr(s), dptr(r), fMax.is_none() ? nullptr : fm.data(), factor.is_none() ? nullptr : w.data(),
	                 wptr(stress), wptr(ft), crush.data());
	finiteResult(stress, "stresses, fMax, radii", "criterion's stress");
	finiteResult(ft, "ft0, radii, m, factor", "strength factor x ft0 / r^m");
	np::ndarray flag = np::zeros(bp::make_tuple(n), np::dtype::get_builtin<bool>());
	std::copy(crush.begin(), crush.end(), reinterpret_cast<bool*>(flag.get_data()));
	return bp::make_tuple(stress, ft, flag);
}

bp::tuple py_abrasionCheck(const bp::object& radii, const bp::object& grain1, const bp::object& grain2, const bp::object& Fn,
                           const bp::object& R1, const bp::object& R2, const bp::object& uN, const bp::object& strength,
                           const bp::object& rMin)
{
	AbrasionParameters p{asScalar(strength, "strength"), asScalar(rMin, "rMin")};
	p.validate();
	np::ndarray r = asDoubles(radii, "radii");
	const long  n = requireShape(r, "radii", {-1}, "a 1-d array");
	np::ndarray g1 = asIndices(grain1, "grain1");
	const long  m  = requireShape(g1, "grain1", {-1}, "a 1-d array");
	std::vector<np::ndarray> c;
	const char*              names[] = {"grain2", "Fn", "R1", "R2", "uN"};
	const bp::object*        objs[]  = {&grain2, &Fn, &R1, &R2, &uN};
	for (int i = 0; i < 5; ++i) {
		c.push_back(i == 0 ? asIndices(*objs[i], names[i]) : asDoubles(*objs[i], names[i]));
		requireShape(c.back(), names[i], {m}, "a 1-d array of length " + std::to_string(m) + ", like grain1");
	}
	np::ndarray               p0 = emptyDoubles({n});
	std::vector<std::uint8_t> ab(n);
	evaluateAbrasion(p, n, dptr(r), m, lptr(g1), lptr(c[0]), dptr(c[1]), dptr(c[2]), dptr(c[3]), dptr(c[4]), wptr(p0), ab.data());
	finiteResult(p0, "Fn, R1, R2, uN", "Hertz pressure");
	np::ndarray flag = np::zeros(bp::make_tuple(n), np::dtype::get_builtin<bool>());
	std::copy(ab.begin(), ab.end(), reinterpret_cast<bool*>(flag.get_data()));
	return bp::make_tuple(p0, flag);
}

bp::tuple py_fatigueCheck(const bp::object& ratio, const bp::object& radii, const bp::object& state, const bp::object& exponent,
                          const bp::object& endurance, const bp::object& hysteresis, const bp::object& rMin)
{
	FatigueParameters p{asScalar(exponent, "exponent"), asScalar(endurance, "endurance"), asScalar(hysteresis, "hysteresis")};
	p.validate();
	np::ndarray s = asDoubles(ratio, "ratio");
	const long  n = requireShape(s, "ratio", {-1}, "a 1-d array");
	np::ndarray r = asDoubles(radii, "radii");
	requireShape(r, "radii", {n}, "an (" + std::to_string(n) + ",) array, one radius per ratio");
	np::ndarray st0 = asDoubles(state, "state");
	requireShape(st0, "state", {n, 4}, "an (" + std::to_string(n) + ",4) array (damage, extreme, rising, peaks) per ratio");
	np::ndarray out = emptyDoubles({n, 4});
	std::copy(dptr(st0), dptr(st0) + 4 * n, wptr(out));
	std::vector<unsigned char> crush(n);
	evaluateFatigue(p, asScalar(rMin, "rMin"), n, dptr(s), dptr(r), reinterpret_cast<GrainFatigue*>(wptr(out)), crush.data());
	finiteResult(out, "ratio, state, exponent", "fatigue damage");
	np::ndarray flag = np::zeros(bp::make_tuple(n), np::dtype::get_builtin<bool>());
	std::copy(crush.begin(), crush.end(), reinterpret_cast<bool*>(flag.get_data()));
	return bp::make_tuple(out, flag);
}

np::ndarray py_abrasionBound(const bp::object& stresses, const bp::object& radii, const bp::object& rPartner,
                             const bp::object& EstarMax)
{
	np::ndarray s = asDoubles(stresses, "stresses");
	np::ndarray r = asDoubles(radii, "radii");
	const long  n = requireShape(r, "radii", {-1}, "a 1-d array");
	requireShape(s, "stresses", {n, 3, 3}, "an (" + std::to_string(n) + ",3,3) array, one tensor per radius");
	std::vector<double> tr(n);
	for (long g = 0; g < n; ++g) {
		tr[g] = dptr(s)[9 * g] + dptr(s)[9 * g + 4] + dptr(s)[9 * g + 8];
		requireFiniteResult("stresses", "trace", g, tr[g]);
	}
	np::ndarray bound = emptyDoubles({n});
	abrasionPressureBound(n, tr.data(), dptr(r), asScalar(rPartner, "rPartner"), asScalar(EstarMax, "EstarMax"), wptr(bound));
	return finiteResult(bound, "stresses, radii, rPartner, EstarMax", "abrasion pressure bound");
}

double py_sphereContactBound(const bp::object& maxOverlapRatio, const bp::object& EstarMax)
{
	const double b = sphereContactBound(asScalar(maxOverlapRatio, "maxOverlapRatio"), asScalar(EstarMax, "EstarMax"));
	requireFiniteResult("maxOverlapRatio, EstarMax", "pressure bound", b);
	return b;
}

bp::object py_contactModulus(const bp::object& E1, const bp::object& nu1, const bp::object& E2, const bp::object& nu2)
{
	return elementwise({{"E1", E1}, {"nu1", nu1}, {"E2", E2}, {"nu2", nu2}}, "contact modulus",
	                   [](const double* x) { return contactModulus(x[0], x[1], x[2], x[3]); });
}

bp::object py_hertzPressureFromForce(const bp::object& Fn, const bp::object& R, const bp::object& Estar)
{
	return elementwise({{"Fn", Fn}, {"R", R}, {"Estar", Estar}}, "Hertz pressure",
	                   [](const double* x) { return hertzPressureFromForce(x[0], x[1], x[2]); });
}

// ---------------------------------------------------------------- fragments (Fig. 1)
Layout toLayout(const bp::object& pattern)
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

np::ndarray matToArray(const Mat3& m)
{
	np::ndarray out = emptyDoubles({3, 3});
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			wptr(out)[3 * i + j] = m(i, j);
	return out;
}

np::ndarray py_fragmentPattern(const bp::object& pattern) { return spheresToArray(fragmentPattern(toLayout(pattern))); }
double      py_keptVolumeFraction(const bp::object& pattern) { return keptVolumeFraction(toLayout(pattern)); }
std::string py_patternName(const bp::object& pattern) { return layoutName(toLayout(pattern)); }

std::uint64_t asSeed(const bp::object& o, const std::string& name)
{
	const bp::object         i = asInteger(o, name, "an integer in [0, 2^64)");
	const unsigned long long v = PyLong_AsUnsignedLongLong(i.ptr());
	if (PyErr_Occurred()) {  // negative, or 2^64 and above
		PyErr_Clear();
		throw ArgumentError(name + ": expected an integer in [0, 2^64), got " + pyStr(i));
	}
	return v;
}

np::ndarray py_weibullFactors(const bp::object& seed, const bp::object& keys, const bp::object& modulus)
{
	const std::uint64_t sd = asSeed(seed, "seed");
	np::ndarray         k  = asIndices(keys, "keys");
	const long          n  = requireShape(k, "keys", {-1}, "a 1-d array");
	std::vector<std::uint64_t> u(n);
	for (long i = 0; i < n; ++i) {
		if (lptr(k)[i] < 0) throw ArgumentError("keys: expected integers >= 0, got " + std::to_string(lptr(k)[i]) + " at index " + std::to_string(i));
		u[i] = (std::uint64_t)lptr(k)[i];
	}
	np::ndarray out = emptyDoubles({n});
	weibullFactors(sd, n, u.data(), asScalar(modulus, "modulus"), wptr(out));
	return finiteResult(out, "modulus", "Weibull factor");
}

np::ndarray py_randomRotation(const bp::object& seed, const bp::object& counter)
{
	return matToArray(randomRotation(asSeed(seed, "seed"), asSeed(counter, "counter")));
}

np::ndarray py_placeFragments(const bp::object& pattern, const bp::object& centre, const bp::object& radius, const bp::object& seed,
                              const bp::object& counter)
{
	const Layout layout = toLayout(pattern);
	np::ndarray  c      = asDoubles(centre, "centre");
	requireShape(c, "centre", {3}, "a 3-vector");
	const double r = asScalar(radius, "radius");
	requirePositive("radius", r);
	const Mat3 rot = randomRotation(asSeed(seed, "seed"), asSeed(counter, "counter"));
	return finiteResult(spheresToArray(placeFragments(layout, Vec3(dptr(c)[0], dptr(c)[1], dptr(c)[2]), r, rot)),
	                    "centre, radius", "fragment position");
}

// ---------------------------------------------------------------- harvesting from YADE
// utils.bodyStressTensors() returns a list of minieigen Matrix3. YADE registers that class with the
// same libboost_python, so the C++ matrix is read in place; anything else goes through numpy.
np::ndarray py_matricesToArray(const bp::object& seq)
{
	bp::list items;
	try {
		items = bp::list(seq);
	} catch (const bp::error_already_set&) {
		PyErr_Clear();
		throw TypeError("matrices: expected a sequence of 3x3 matrices, got " + pyStr(seq.attr("__class__").attr("__name__")));
	}
	const long  n   = bp::len(items);
	np::ndarray out = emptyDoubles({n, 3, 3});
	double*     o   = wptr(out);
	for (long i = 0; i < n; ++i) {
		bp::object                        item = items[i];
		bp::extract<const Eigen::Matrix3d&> m(item);
		if (m.check()) {
			const Eigen::Matrix3d& M = m();
			for (int a = 0; a < 3; ++a)
				for (int b = 0; b < 3; ++b) {
					requireFinite("matrices", i, M(a, b));  // the numpy path checks this in asDoubles
					o[9 * i + 3 * a + b] = M(a, b);
				}
		} else {
			np::ndarray a = asDoubles(item, "matrices[" + std::to_string(i) + "]");
			requireShape(a, "matrices[" + std::to_string(i) + "]", {3, 3}, "a 3x3 matrix");
			std::copy(dptr(a), dptr(a) + 9, o + 9 * i);
		}
	}
	return out;
}

bool py_fastMatrixPath(const bp::object& item) { return bp::extract<const Eigen::Matrix3d&>(item).check(); }

void translateArgument(const ArgumentError& e) { PyErr_SetString(PyExc_ValueError, e.what()); }
void translateType(const TypeError& e) { PyErr_SetString(PyExc_TypeError, e.what()); }

}  // namespace

BOOST_PYTHON_MODULE(_ballast)
{
	np::initialize();
	bp::register_exception_translator<ArgumentError>(&translateArgument);
	bp::register_exception_translator<TypeError>(&translateType);
	bp::scope().attr("__doc__") = "C++ core of the crushable-ballast model (Dubina & Elias). See the ballast package.";

	bp::def("fabricStress", py_fabricStress, (bp::arg("radius"), "branches", "forces"),
	        "Fabric (Love-Weber) stress of one grain, eq. 3 [Pa]: (1/V) sum_c l^c (x) F^c, V = 4/3 pi r^3.\n"
	        "radius [m] > 0; branches (n,3) [m] from the grain centre to each contact point; forces (n,3) [N] acting on the grain.\n"
	        "Returns a (3,3) array, compression negative.");
	bp::def("grainStresses", py_grainStresses, (bp::arg("radii"), "grainIndex", "branches", "forces"),
	        "Eq. 3 for many grains from flat contact arrays: radii (N,) [m]; grainIndex (M,) integers in [0,N);\n"
	        "branches (M,3) [m]; forces (M,3) [N]. Returns (N,3,3) [Pa].");
	bp::def("vonMises", py_vonMises, (bp::arg("sigma")),
	        "Von Mises stress, eq. 2 [Pa], of the symmetric part of sigma: (3,3) -> float, (N,3,3) -> (N,).");
	bp::def("principalStresses", py_principalStresses, (bp::arg("sigma")),
	        "Principal stresses of the symmetric part, sorted sI >= sII >= sIII [Pa]: (3,3) -> (3,), (N,3,3) -> (N,3).");
	bp::def("hertzPressure", py_hertzPressure, (bp::arg("Fn"), "R1", "R2", "uN"),
	        "Maximum Hertz pressure, eq. 7 [Pa]: p0 = 3 Fn / (2 pi R uN), R = R1 R2 / (R1 + R2).\n"
	        "Fn [N], R1, R2 [m], uN overlap [m]; scalars or arrays (broadcast). A radius of 0 is a flat wall\n"
	        "(R2 = 0 gives R = R1). No compression (Fn <= 0 or uN <= 0) gives 0.");
	bp::def("effectiveRadius", py_effectiveRadius, (bp::arg("R1"), "R2"), "R1 R2 / (R1 + R2) [m]; 0 is a wall.");
	bp::def("sizeStrength", py_sizeStrength, (bp::arg("ft0"), "radius", bp::arg("m") = 1.0),
	        "Size-dependent strength, eq. 4 [Pa]: ft0 / r^m; ft0 [Pa m^m], radius [m], m [-] (paper: 1).");
	bp::def("crushCheck", py_crushCheck,
	        (bp::arg("stresses"), "radii", "ft0", "m", "rMin", bp::arg("criterion") = "vonMises", bp::arg("fMax") = bp::object(),
	         bp::arg("factor") = bp::object()),
	        "Crushing decision for all grains (eq. 1): stresses (N,3,3) [Pa], radii (N,) [m]; criterion 'vonMises' (eq. 2),\n"
	        "'maxContactForce' (fMax / d^2, fMax (N,) [N] the largest normal contact force of each grain) or\n"
	        "'majorPrincipal'; factor (N,) [-] each grain's strength factor (None: 1).\n"
	        "Returns (stress (N,) [Pa], strength factor x ft0 / r^m (N,) [Pa], crush (N,) bool); r < rMin never crush.");
	bp::def("weibullFactors", py_weibullFactors, (bp::arg("seed"), "keys", "modulus"),
	        "Weibull strength factors (docs/strength.md): w = (-ln U)^(1/modulus), U uniform from (seed, key), one per\n"
	        "key (N,) integers >= 0; modulus 0 gives 1. Reproducible and independent of the order of the keys.");
	bp::def("fatigueCheck", py_fatigueCheck, (bp::arg("ratio"), "radii", "state", "exponent", "endurance", "hysteresis", "rMin"),
	        "Fatigue (docs/fatigue.md): one sample of the stress ratio sigma_e / f_t (N,) [-] of grains of radii (N,) [m],\n"
	        "their state (N,4) (damage D, running extreme, rising 0/1, damaging peaks; a new grain is 0, 0, 1, 0);\n"
	        "a peak >= endurance [-] ends when the ratio falls hysteresis [-] below it and adds peak^exponent to D.\n"
	        "Returns (the new state (N,4), crush (N,) bool: r >= rMin and ratio > 1 - D).");
	bp::def("abrasionCheck", py_abrasionCheck, (bp::arg("radii"), "grain1", "grain2", "Fn", "R1", "R2", "uN", "strength", "rMin"),
	        "Abrasion decision for all grains (eq. 6 with eq. 7): radii (N,) [m]; per contact (M,): grain1, grain2 the grain\n"
	        "index of each side or -1, Fn [N], R1, R2 [m] (0 = wall), uN [m]; strength [Pa]; rMin [m].\n"
	        "Returns (p0max (N,) [Pa], abrade (N,) bool).");
	bp::def("abrasionBound", py_abrasionBound, (bp::arg("stresses"), "radii", "rPartner", "EstarMax"),
	        "Upper bound of p0 (eq. 7) over the Hertzian contacts of each grain with bodies of radius >= rPartner [m]\n"
	        "(0: walls and facets), from its fabric stress alone: stresses (N,3,3) [Pa] (eq. 3), radii (N,) [m],\n"
	        "EstarMax the largest contact modulus [Pa]. Returns (N,) [Pa].");
	bp::def("sphereContactBound", py_sphereContactBound, (bp::arg("maxOverlapRatio"), "EstarMax"),
	        "Upper bound of p0 (eq. 7) over all Hertzian sphere-sphere contacts, (2 E*/pi) sqrt(2 rho) [Pa], from\n"
	        "rho = max u_N / (2 R) (utils.maxOverlapRatio()) and the largest contact modulus EstarMax [Pa].");
	bp::def("contactModulus", py_contactModulus, (bp::arg("E1"), "nu1", "E2", "nu2"),
	        "Hertz contact modulus E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa]; scalars or arrays.");
	bp::def("hertzPressureFromForce", py_hertzPressureFromForce, (bp::arg("Fn"), "R", "Estar"),
	        "Eq. 7 on a Hertzian contact from the force alone: (6 Fn E*^2 / (pi^3 R^2))^(1/3) [Pa]; Fn [N],\n"
	        "R effective radius [m], Estar contact modulus [Pa]; scalars or arrays. Fn <= 0 gives 0.");
	bp::def("fragmentPattern", py_fragmentPattern, (bp::arg("pattern")),
	        "Fragments of a unit parent at the origin as an (n,4) array [x,y,z,r]: pattern 4 (tetra4), 6 (octa6),\n"
	        "14 (fill14), or the names 'tetra4', 'planar4', 'octa6', 'fill14'.");
	bp::def("keptVolumeFraction", py_keptVolumeFraction, (bp::arg("pattern")), "Fragment volume / parent volume [-].");
	bp::def("patternName", py_patternName, (bp::arg("pattern")), "Canonical name of a pattern ('tetra4', ...).");
	bp::def("randomRotation", py_randomRotation, (bp::arg("seed"), "counter"),
	        "Uniform random rotation matrix (3,3), the same for the same (seed, counter) on every platform.");
	bp::def("placeFragments", py_placeFragments, (bp::arg("pattern"), "centre", "radius", "seed", "counter"),
	        "Fragments of a parent of the given radius [m] and centre [m], randomly rotated by (seed, counter): (n,4).");
	bp::def("matricesToArray", py_matricesToArray, (bp::arg("matrices")),
	        "A sequence of 3x3 matrices (e.g. utils.bodyStressTensors()) as an (N,3,3) array, read in C++.");
	bp::def("_fastMatrixPath", py_fastMatrixPath, (bp::arg("item")), "True if item is read in place as a C++ Eigen matrix.");
}
