// Binding of ClumpSplit.hpp: how a crushed clump splits, its members shared out among pieces.
#include <cstring>
#include <string>

#include "../ClumpSplit.hpp"
#include "../InputCheck.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	np::ndarray longs(const std::vector<long>& v, long rows, long cols)
	{
		np::ndarray a = cols ? np::empty(bp::make_tuple(rows, cols), np::dtype::get_builtin<long>())
		                     : np::empty(bp::make_tuple(rows), np::dtype::get_builtin<long>());
		if (!v.empty()) std::memcpy(reinterpret_cast<long*>(a.get_data()), v.data(), v.size() * sizeof(long));
		return a;
	}

	bp::dict clumpSplitOf(const bp::object& stress, const bp::object& centre, const bp::object& memberPositions,
	                      const bp::object& memberRadii)
	{
		np::ndarray s = asDoubles(stress, "stress");
		requireShape(s, "stress", {3, 3}, "a (3,3) stress tensor");
		np::ndarray X = asDoubles(centre, "centre");
		requireShape(X, "centre", {3}, "a (3,) centre of mass");
		np::ndarray x = asDoubles(memberPositions, "memberPositions");
		const long  m = requireShape(x, "memberPositions", {-1, 3}, "an (m,3) array of member centres, m >= 1");
		if (m < 1) throw ArgumentError("memberPositions: expected an (m,3) array of member centres with m >= 1, got "
		                               "shape " + shapeOf(x));
		np::ndarray r = asDoubles(memberRadii, "memberRadii");
		requireShape(r, "memberRadii", {m}, "a 1-d array of " + std::to_string(m) + ", one radius per member");
		const ClumpSplit c = clumpSplit(dptr(s), dptr(X), static_cast<int>(m), dptr(x), dptr(r));
		np::ndarray normals = emptyDoubles({(long)c.normals.size() / 3, 3});
		std::memcpy(wptr(normals), c.normals.data(), c.normals.size() * sizeof(double));
		bp::dict out;
		out["piece"]   = longs(c.piece, m, 0);
		out["nPieces"] = c.nPieces;
		out["normals"] = normals;
		out["median"]  = c.median;
		out["pairs"]   = longs(c.pairs, (long)c.pairs.size() / 2, 2);
		return out;
	}
}  // namespace

void registerClumpSplit()
{
	bp::def("clumpSplit", clumpSplitOf, (bp::arg("stress"), "centre", "memberPositions", "memberRadii"),
	        "How a crushed clump splits (docs/grains.md, \"Crushing a clump\"): planes through its centre of mass normal\n"
	        "to its most tensile principal direction n1, and to n2 when that is tensile relative to the mean stress;\n"
	        "directions within coinciding principal values from the members' spread. stress (3,3) [Pa] the clump's\n"
	        "(tension positive, its symmetric part used), centre (3,) [m], memberPositions (m,3) [m], memberRadii (m,)\n"
	        "[m] > 0. Returns a dict: piece (m,) the piece of each member (0 ... nPieces-1, numbered by first member),\n"
	        "nPieces, normals (1 or 2, 3) the unit plane normals, median (True when all members fell on one side and\n"
	        "were halved at their median projection instead), pairs (p,2) the member indices (i < j) of different\n"
	        "pieces whose spheres overlap.");
}

}  // namespace binding
}  // namespace ballast
