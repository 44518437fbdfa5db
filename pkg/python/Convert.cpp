#include "Convert.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../InputCheck.hpp"

namespace ballast {
namespace binding {

namespace {
	void translateArgument(const ArgumentError& e) { PyErr_SetString(PyExc_ValueError, e.what()); }
	void translateType(const TypeError& e) { PyErr_SetString(PyExc_TypeError, e.what()); }

	// Converts obj to a C-contiguous array of dtype (float64 or int64), accepting only the dtype kinds given.
	np::ndarray asArray(const bp::object& obj, const std::string& name, const char* kinds, const np::dtype& dt)
	{
		// what numpy.require would return unchanged, without its Python calls (the engines' every check)
		bp::extract<np::ndarray> already(obj);
		if (already.check()) {
			np::ndarray a = already();
			if (a.get_dtype() == dt && (a.get_flags() & np::ndarray::C_CONTIGUOUS)) return a;
		}
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

	// An integer in [0, 2^64), else an error with the range in words.
	std::uint64_t asUnsigned(const bp::object& obj, const std::string& name, const std::string& words)
	{
		const bp::object         i = asInteger(obj, name, words);
		const unsigned long long v = PyLong_AsUnsignedLongLong(i.ptr());
		if (PyErr_Occurred()) {  // negative, or 2^64 and above
			PyErr_Clear();
			throw ArgumentError(name + ": expected " + words + ", got " + pyStr(i));
		}
		return v;
	}
}  // namespace

void registerErrorTranslators()
{
	bp::register_exception_translator<ArgumentError>(&translateArgument);
	bp::register_exception_translator<TypeError>(&translateType);
}

std::string pyStr(const bp::object& o) { return bp::extract<std::string>(bp::str(o)); }

std::string shapeOf(const np::ndarray& a)
{
	std::string s = "(";
	for (int i = 0; i < a.get_nd(); ++i)
		s += std::to_string(a.shape(i)) + (a.get_nd() == 1 || i + 1 < a.get_nd() ? "," : "");
	return s + ")";
}

long sizeOf(const np::ndarray& a)
{
	long n = 1;
	for (int i = 0; i < a.get_nd(); ++i)
		n *= a.shape(i);
	return n;
}

np::ndarray asDoubles(const bp::object& obj, const std::string& name)
{
	np::ndarray a = asArray(obj, name, "iuf", np::dtype::get_builtin<double>());
	const long  n = sizeOf(a);
	const auto* p = dptr(a);
	for (long i = 0; i < n; ++i)
		if (!std::isfinite(p[i]))
			throw ArgumentError(name + ": expected finite numbers, got " + formatValue(p[i]) + " at flat index " + std::to_string(i));
	return a;
}

np::ndarray asIndices(const bp::object& obj, const std::string& name)
{
	return asArray(obj, name, "iu", np::dtype::get_builtin<long>());
}

long requireShape(const np::ndarray& a, const std::string& name, const std::vector<long>& want, const std::string& what)
{
	bool ok = a.get_nd() == (int)want.size();
	for (int i = 0; ok && i < a.get_nd(); ++i)
		ok = want[i] < 0 || a.shape(i) == want[i];
	if (!ok) throw TypeError(name + ": expected " + what + ", got shape " + shapeOf(a));
	return want.empty() ? 1 : a.shape(0);
}

GrainStressArrays asGrainStresses(const bp::object& stresses, const bp::object& radii)
{
	np::ndarray s = asDoubles(stresses, "stresses");
	np::ndarray r = asDoubles(radii, "radii");
	const long  n = requireShape(r, "radii", {-1}, "a 1-d array");
	requireShape(s, "stresses", {n, 3, 3}, "an (" + std::to_string(n) + ",3,3) array, one tensor per radius");
	return {s, r, n};
}

np::ndarray emptyDoubles(const std::vector<long>& shape)
{
	std::vector<Py_intptr_t> s(shape.begin(), shape.end());
	return np::zeros(s.size(), s.data(), np::dtype::get_builtin<double>());
}

np::ndarray boolArray(const std::vector<std::uint8_t>& flags)
{
	np::ndarray out = np::zeros(bp::make_tuple(flags.size()), np::dtype::get_builtin<bool>());
	std::copy(flags.begin(), flags.end(), reinterpret_cast<bool*>(out.get_data()));
	return out;
}

double asScalar(const bp::object& obj, const std::string& name)
{
	if (PyFloat_Check(obj.ptr())) {  // a Python float: no array needed
		const double v = PyFloat_AS_DOUBLE(obj.ptr());
		requireFinite(name, v);
		return v;
	}
	np::ndarray a = asArray(obj, name, "iuf", np::dtype::get_builtin<double>());
	if (a.get_nd() != 0) throw TypeError(name + ": expected a number, got an array of shape " + shapeOf(a));
	requireFinite(name, *dptr(a));
	return *dptr(a);
}

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

std::uint64_t asSeed(const bp::object& obj)
{
	return requireInRange(ranges::seed, "seed", asUnsigned(obj, "seed", ranges::seed.words));
}

std::uint64_t asCounter(const bp::object& obj, const std::string& name)
{
	return asUnsigned(obj, name, "an integer in [0, 2^64)");
}

const np::ndarray& finiteResult(const np::ndarray& out, const char* names, const char* what, bool indexed)
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

bp::object elementwise(const std::vector<std::pair<std::string, bp::object>>& args, const char* what,
                       double (*fn)(const double*))
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
	const long          n   = sizeOf(c[0]);
	np::ndarray         out = bp::extract<np::ndarray>(numpy.attr("zeros")(bp::object(c[0].attr("shape")), "float64"));
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

}  // namespace binding
}  // namespace ballast
