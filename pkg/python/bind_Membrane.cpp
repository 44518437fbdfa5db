// Binding of Membrane.hpp: the membrane's load on a triaxial specimen's grains, arrays in and out.
#include <cstring>

#include "../InputCheck.hpp"
#include "../Membrane.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	const long kMaxCells = 100000000L;  // cells around or along: more than any specimen needs (the core bounds both)

	long asCount(const bp::object& obj, const std::string& name, long lowest)
	{
		const std::string range = "an integer in [" + std::to_string(lowest) + ", 1e8]";
		const bp::object  v     = asInteger(obj, name, range);
		if (!bp::extract<bool>(v >= lowest)() || !bp::extract<bool>(v <= kMaxCells)())  // before a C long holds it
			throw ArgumentError(name + ": expected " + range + ", got " + pyStr(v));
		return bp::extract<long>(v);
	}

	bp::dict membraneLoadOf(const bp::object& centres, const bp::object& radii, const bp::object& pressure,
	                        const bp::object& axisX, const bp::object& axisY, const bp::object& z0, const bp::object& z1,
	                        const bp::object& nTheta, const bp::object& nZ, const bp::object& depth)
	{
		const MembraneGrid g = MembraneGrid::checked(asScalar(axisX, "axisX"), asScalar(axisY, "axisY"),
		                                             asScalar(z0, "z0"), asScalar(z1, "z1"), asCount(nTheta, "nTheta", 3),
		                                             asCount(nZ, "nZ", 1), asScalar(depth, "depth"));
		np::ndarray c = asDoubles(centres, "centres");
		const long  n = requireShape(c, "centres", {-1, 3}, "an (N,3) array of grain centres");
		np::ndarray r = asDoubles(radii, "radii");
		requireShape(r, "radii", {n}, "an (N,) array of grain radii, one per centre");
		const MembraneLoad m = membraneLoad(g, n, dptr(c), dptr(r), asScalar(pressure, "pressure"));
		np::ndarray force = emptyDoubles({n, 3}), radius = emptyDoubles({g.nZ, g.nTheta});
		std::memcpy(wptr(force), m.force.data(), m.force.size() * sizeof(double));
		std::memcpy(wptr(radius), m.radius.data(), m.radius.size() * sizeof(double));
		np::ndarray owner = np::empty(bp::make_tuple(g.nZ, g.nTheta), np::dtype::get_builtin<long>());
		std::memcpy(reinterpret_cast<long*>(owner.get_data()), m.owner.data(), m.owner.size() * sizeof(long));
		bp::dict out;
		out["force"]   = force;
		out["radius"]  = radius;
		out["owner"]   = owner;
		out["bridged"] = m.bridged;
		out["empty"]   = m.empty;
		out["area"]    = m.area;
		out["volume"]  = m.volume;
		return out;
	}
}  // namespace

void registerMembrane()
{
	bp::def("membraneLoad", membraneLoadOf,
	        (bp::arg("centres"), "radii", "pressure", "axisX", "axisY", "z0", "z1", "nTheta", "nZ", "depth"),
	        "The flexible membrane of a cylindrical triaxial specimen (docs/triaxial.md, \"The membrane\"): the pressure\n"
	        "[Pa] on the lateral surface between the platens z0 < z1 [m] around the vertical axis (axisX, axisY) [m],\n"
	        "cut into nTheta x nZ cells, each resting where a radial ray meets the outermost grain (spanning gaps\n"
	        "deeper than depth [m]) and passing p times its area to that grain, horizontally towards the axis.\n"
	        "centres (N,3) [m], radii (N,) [m]. Returns a dict: force (N,3) [N], radius (nZ,nTheta) [m] the membrane's\n"
	        "radius per cell, owner (nZ,nTheta) the grain index carrying each cell (-1: none), bridged and empty cell\n"
	        "counts, area [m^2] and volume [m^3] it encloses.");
}

}  // namespace binding
}  // namespace ballast
