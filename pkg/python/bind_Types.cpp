// Binding of Types.hpp: YADE's minieigen Matrix3 is an Eigen::Matrix3d (ballast::Mat3), read in place.
#include <algorithm>
#include <string>

#include "../InputCheck.hpp"
#include "../Types.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	// utils.bodyStressTensors() returns a list of minieigen Matrix3. YADE registers that class with the
	// same libboost_python, so the C++ matrix is read in place; anything else goes through numpy.
	np::ndarray matricesToArray(const bp::object& seq)
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
			bp::object             item = items[i];
			bp::extract<const Mat3&> m(item);
			if (m.check()) {
				const Mat3& M = m();
				for (int a = 0; a < 3; ++a)
					for (int b = 0; b < 3; ++b) {
						requireFinite("matrices", i, M(a, b));  // the numpy path checks this in asDoubles
						o[9 * i + 3 * a + b] = M(a, b);
					}
			} else {
				const std::string name = "matrices[" + std::to_string(i) + "]";
				np::ndarray       a    = asDoubles(item, name);
				requireShape(a, name, {3, 3}, "a 3x3 matrix");
				std::copy(dptr(a), dptr(a) + 9, o + 9 * i);
			}
		}
		return out;
	}

	bool fastMatrixPath(const bp::object& item) { return bp::extract<const Mat3&>(item).check(); }
}  // namespace

void registerTypes()
{
	bp::def("matricesToArray", matricesToArray, (bp::arg("matrices")),
	        "A sequence of 3x3 matrices (e.g. utils.bodyStressTensors()) as an (N,3,3) array, read in C++.");
	bp::def("_fastMatrixPath", fastMatrixPath, (bp::arg("item")), "True if item is read in place as a C++ Eigen matrix.");
}

}  // namespace binding
}  // namespace ballast
