// Binding of VonMises.hpp: the equivalent stress of eq. 2 and the principal stresses, of one tensor or many.
#include "../InputCheck.hpp"
#include "../VonMises.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	const char* const kTensors = "a (3,3) or (N,3,3) array";

	// Row-major storage read as column-major is the transpose: both functions use the symmetric part.
	Eigen::Map<const Mat3> tensor(const np::ndarray& s, long i) { return Eigen::Map<const Mat3>(dptr(s) + 9 * i); }

	bp::object vonMisesOf(const bp::object& sigma)
	{
		np::ndarray s = asDoubles(sigma, "sigma");
		if (s.get_nd() == 2) {
			requireShape(s, "sigma", {3, 3}, kTensors);
			const double v = vonMises(tensor(s, 0));
			requireFiniteResult("sigma", "von Mises stress", v);
			return bp::object(v);
		}
		const long  n   = requireShape(s, "sigma", {-1, 3, 3}, kTensors);
		np::ndarray out = emptyDoubles({n});
		for (long i = 0; i < n; ++i)
			wptr(out)[i] = vonMises(tensor(s, i));
		return finiteResult(out, "sigma", "von Mises stress");
	}

	np::ndarray principalStressesOf(const bp::object& sigma)
	{
		np::ndarray s   = asDoubles(sigma, "sigma");
		const bool  one = s.get_nd() == 2;
		const long  n   = one ? (requireShape(s, "sigma", {3, 3}, kTensors), 1L) : requireShape(s, "sigma", {-1, 3, 3}, kTensors);
		np::ndarray out = one ? emptyDoubles({3}) : emptyDoubles({n, 3});
		for (long i = 0; i < n; ++i) {
			const Vec3 p = principalStresses(tensor(s, i));
			for (int k = 0; k < 3; ++k)
				wptr(out)[3 * i + k] = p[k];
		}
		return finiteResult(out, "sigma", "principal stress", !one);
	}
}  // namespace

void registerVonMises()
{
	bp::def("vonMises", vonMisesOf, (bp::arg("sigma")),
	        "Von Mises stress, eq. 2 [Pa], of the symmetric part of sigma: (3,3) -> float, (N,3,3) -> (N,).");
	bp::def("principalStresses", principalStressesOf, (bp::arg("sigma")),
	        "Principal stresses of the symmetric part, sorted sI >= sII >= sIII [Pa]: (3,3) -> (3,), (N,3,3) -> (N,3).");
}

}  // namespace binding
}  // namespace ballast
