#include "CrushCriterion.hpp"

#include <algorithm>

#include "InputCheck.hpp"
#include "VonMises.hpp"

namespace ballast {

Criterion parseCriterion(const std::string& name)
{
	if (name == "vonMises") return Criterion::VonMises;
	if (name == "maxContactForce") return Criterion::MaxContactForce;
	if (name == "majorPrincipal") return Criterion::MajorPrincipal;
	throw ArgumentError("criterion: expected 'vonMises', 'maxContactForce' or 'majorPrincipal', got '" + name + "'");
}

const char* criterionName(Criterion c)
{
	switch (c) {
		case Criterion::VonMises: return "vonMises";
		case Criterion::MaxContactForce: return "maxContactForce";
		default: return "majorPrincipal";
	}
}

double criterionStress(Criterion c, const Mat3& s, double fMax, double r)
{
	switch (c) {
		case Criterion::VonMises: return vonMises(s);
		case Criterion::MaxContactForce: return fMax / (4 * r * r);
		default: return std::max(0.0, -principalStresses(s)[2]);  // sorted sI >= sII >= sIII
	}
}

}  // namespace ballast
