#include "CrushCriterion.hpp"

#include <algorithm>

#include "InputCheck.hpp"
#include "VonMises.hpp"

namespace ballast {

const std::vector<Criterion>& criteria()
{
	static const std::vector<Criterion> all = {Criterion::VonMises, Criterion::MaxContactForce, Criterion::MajorPrincipal};
	return all;
}

Criterion parseCriterion(const std::string& name)
{
	std::string names;  // "'vonMises', 'maxContactForce' or 'majorPrincipal'"
	for (size_t i = 0; i < criteria().size(); ++i) {
		const Criterion c = criteria()[i];
		if (name == criterionName(c)) return c;
		names += std::string(i == 0 ? "" : i + 1 < criteria().size() ? ", " : " or ") + "'" + criterionName(c) + "'";
	}
	throw ArgumentError("criterion: expected " + names + ", got '" + name + "'");
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
