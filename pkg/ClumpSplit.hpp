// Bulk crushing of a clump grain (issue 47, item 2): the clump splits into pieces along planes through its
// centre of mass X, oriented by its principal stresses; its members are shared out among the pieces, not
// replaced, so mass and volume are kept and no member is lost or duplicated.
//
// The planes (docs/grains.md, "Crushing a clump"). With sigma's principal values l1 >= l2 >= l3 (tension
// positive) and directions n1, n2, n3, and the deviatoric values s_i = l_i - (l1 + l2 + l3)/3:
//   * plane 1 is normal to n1, the most tensile direction: a brittle grain opens across its largest tension
//     (Elias 2014's PolyhedraSplitter cuts normal to the largest principal stress);
//   * plane 2 is normal to n2 when s2 > 0, i.e. when n2 is tensile relative to the mean stress as well. Under
//     uniaxial compression (s1 = s2 > 0) both planes contain the loading axis: four wedges, the axial splitting
//     of a grain crushed between platens; under uniaxial tension (s2 < 0) one plane: two pieces.
//   * where principal values coincide (|l_i - l_j| <= 1e-9 max|l|), the direction within that eigenspace is not
//     set by the stress; it is taken from the members' spread (the second moment sum r_m^3 (x_m - X)(x_m - X)^T
//     projected on the eigenspace, largest first): the cut goes across the grain's longest extent there.
// Member m goes to piece (d1 > 0) + 2 (d2 > 0), d_k = (x_m - X).n_k; empty pieces are dropped and the pieces are
// numbered in the order of their first member. If every member falls in one piece (a clump of n >= 2 members),
// the members are split in two at the median of their projections on n1 (else n2, n3: the first along which
// they differ), so a crushed clump of two or more members always gives at least two pieces.
#pragma once

#include <vector>

namespace ballast {

struct ClumpSplit {
	std::vector<long>   piece;    // piece index of each member, 0 ... nPieces - 1
	int                 nPieces = 0;
	std::vector<double> normals;  // the unit plane normals used, 3 per plane (1 or 2 planes), row-major
	bool                median = false;  // the median fallback was used (all members were on one side)
	std::vector<long>   pairs;    // members (i, j), i < j, of different pieces whose spheres overlap: 2 per pair
};

// stress: the clump's 3x3 stress (row-major; its symmetric part is used), centre X (3), nMembers >= 1 members of
// centres memberPos (3 nMembers) and radii memberRadius (nMembers, > 0).
ClumpSplit clumpSplit(const double* stress, const double* centre, int nMembers, const double* memberPos,
                      const double* memberRadius);

}  // namespace ballast
