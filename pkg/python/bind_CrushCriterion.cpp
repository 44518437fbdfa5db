// Binding of CrushCriterion.hpp: the names of the crushing criteria (ballast.params checks `criterion` with them).
#include "../CrushCriterion.hpp"
#include "Convert.hpp"

namespace ballast {
namespace binding {

namespace {
	bp::tuple criterionNames()
	{
		bp::list names;
		for (Criterion c : criteria())
			names.append(criterionName(c));
		return bp::tuple(names);
	}
}  // namespace

void registerCrushCriterion()
{
	bp::def("criterionNames", criterionNames,
	        "The names crushCheck takes as criterion, the paper's first: ('vonMises', 'maxContactForce', 'majorPrincipal').");
}

}  // namespace binding
}  // namespace ballast
