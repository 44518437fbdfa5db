// Conversions shared by the binding files of ballast._ballast (one file per core header, bind_<Header>.cpp):
// Python objects to C-contiguous NumPy arrays and numbers, results back, and bad input to Python errors:
// TypeError (wrong type, dtype or shape) or ValueError (ArgumentError: a bad value, or a result that
// would not be finite), each naming the argument. NumPy scalars and 0-d arrays are taken wherever
// Python numbers are.
#pragma once
#include <boost/python.hpp>
#include <boost/python/numpy.hpp>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ballast {
namespace binding {

namespace bp = boost::python;
namespace np = boost::python::numpy;

// Thrown for a wrong type, dtype or shape; becomes Python's TypeError (ArgumentError becomes ValueError).
struct TypeError : std::runtime_error {
	explicit TypeError(const std::string& what) : std::runtime_error(what) {}
};

// Registers the translation of TypeError and ArgumentError into Python exceptions.
void registerErrorTranslators();

std::string pyStr(const bp::object& o);
std::string shapeOf(const np::ndarray& a);  // "(3,)", "(2,3)"
long        sizeOf(const np::ndarray& a);   // number of elements

// obj as a C-contiguous float64 array of finite numbers (ints, floats, NumPy scalars, nested lists).
np::ndarray asDoubles(const bp::object& obj, const std::string& name);
// obj as a C-contiguous int64 array (integers only; uint64 above 2^63 - 1 refused).
np::ndarray asIndices(const bp::object& obj, const std::string& name);
// Checks the shape; -1 in want is any length. Returns the first dimension (1 for a 0-d array).
long requireShape(const np::ndarray& a, const std::string& name, const std::vector<long>& want, const std::string& what);

// The fabric stresses of N grains, stresses (N,3,3) [Pa] one tensor per radius of radii (N,) [m], as arrays.
struct GrainStressArrays {
	np::ndarray stresses, radii;
	long        n;
};
GrainStressArrays asGrainStresses(const bp::object& stresses, const bp::object& radii);

inline const double* dptr(const np::ndarray& a) { return reinterpret_cast<const double*>(a.get_data()); }
inline const long*   lptr(const np::ndarray& a) { return reinterpret_cast<const long*>(a.get_data()); }
inline double*       wptr(np::ndarray& a) { return reinterpret_cast<double*>(a.get_data()); }

// A zero-filled float64 array of the shape.
np::ndarray emptyDoubles(const std::vector<long>& shape);
// A bool array of the flags (0/1), one per grain.
np::ndarray boolArray(const std::vector<std::uint8_t>& flags);

// A finite real number: Python int or float, NumPy integer or float scalar, or 0-d array.
double asScalar(const bp::object& obj, const std::string& name);
// An integer: Python int, NumPy integer scalar or 0-d integer array, as a Python int. Bools are refused
// (NumPy still lets np.bool_ pass as an index), and so are floats, even 6.0; what is the range in words.
bp::object asInteger(const bp::object& obj, const std::string& name, const std::string& what);
// The engines' seed, an integer in its range (InputCheck.hpp: ranges::seed).
std::uint64_t asSeed(const bp::object& obj);
// Any integer in [0, 2^64) (the counter of fragment orientations).
std::uint64_t asCounter(const bp::object& obj, const std::string& name);

// Refuses a result that is not finite (an overflow, or a division by an underflowed number), naming the
// arguments it is computed from; the error gives the first index of the result (a grain, a contact)
// unless the result is one value or one tensor (indexed false). Returns out.
const np::ndarray& finiteResult(const np::ndarray& out, const char* names, const char* what, bool indexed = true);

// fn applied elementwise to the arguments (name, value) broadcast like NumPy; a float when all are
// scalars, else an array. what names the result in the error of a non-finite one.
bp::object elementwise(const std::vector<std::pair<std::string, bp::object>>& args, const char* what,
                       double (*fn)(const double*));

}  // namespace binding
}  // namespace ballast
