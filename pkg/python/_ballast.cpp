// Python module `ballast._ballast`: the C++ core bound with Boost.Python + Boost.Python NumPy, one binding
// file per core header (bind_<Header>.cpp, each with its register function), conversions in Convert.hpp.
// Arrays in, arrays out: every loop over grains or contacts runs in C++, never in Python.
#include "Convert.hpp"

namespace ballast {
namespace binding {
	void registerFabricStress();
	void registerVonMises();
	void registerHertzPressure();
	void registerStrength();
	void registerCrushCriterion();
	void registerBallastCrushEngine();
	void registerWeibull();
	void registerFatigue();
	void registerCycleJump();
	void registerBallastAbrasionEngine();
	void registerFragmentPattern();
	void registerInputCheck();
	void registerTypes();
	void registerDensityScaling();
	void registerInertialNumber();
	void registerMembrane();
	void registerClumpStress();
	void registerClumpSplit();
}  // namespace binding
}  // namespace ballast

BOOST_PYTHON_MODULE(_ballast)
{
	using namespace ballast::binding;
	np::initialize();
	registerErrorTranslators();
	bp::scope().attr("__doc__") = "C++ core of the crushable-ballast model (Dubina & Elias). See the ballast package.";
	registerFabricStress();
	registerVonMises();
	registerHertzPressure();
	registerStrength();
	registerCrushCriterion();
	registerBallastCrushEngine();
	registerWeibull();
	registerFatigue();
	registerCycleJump();
	registerBallastAbrasionEngine();
	registerFragmentPattern();
	registerInputCheck();
	registerTypes();
	registerDensityScaling();
	registerInertialNumber();
	registerMembrane();
	registerClumpStress();
	registerClumpSplit();
}
