#include "ClumpSplit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "InputCheck.hpp"

namespace ballast {

namespace {
	constexpr double kSame = 1e-9;  // principal values closer than this times max|l| are one eigenspace

	// The columns of B (an orthonormal basis of an eigenspace) turned to the members' principal spread in it,
	// largest spread first.
	Eigen::MatrixXd bySpread(const Eigen::MatrixXd& B, const Eigen::Matrix3d& spread)
	{
		Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e(B.transpose() * spread * B);
		return B * e.eigenvectors().rowwise().reverse();  // Eigen sorts ascending
	}

	// A sign convention so equal inputs give equal normals: the largest component positive.
	Eigen::Vector3d canonical(Eigen::Vector3d n)
	{
		int k;
		n.cwiseAbs().maxCoeff(&k);
		return n[k] < 0 ? Eigen::Vector3d(-n) : n;
	}
}  // namespace

ClumpSplit clumpSplit(const double* stress, const double* centre, int nMembers, const double* memberPos,
                      const double* memberRadius)
{
	if (nMembers < 1) throw ArgumentError("nMembers: expected >= 1 (a clump has members), got " + std::to_string(nMembers));
	for (int i = 0; i < 9; ++i)
		requireFinite("stress", i, stress[i]);
	for (int i = 0; i < 3; ++i)
		requireFinite("centre", i, centre[i]);
	for (int m = 0; m < nMembers; ++m) {
		requirePositive("memberRadii", m, memberRadius[m]);
		for (int i = 0; i < 3; ++i)
			requireFinite("memberPositions", m, memberPos[3 * m + i]);
	}
	const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> S(stress);
	const Eigen::Vector3d X(centre[0], centre[1], centre[2]);
	std::vector<Eigen::Vector3d> rel(nMembers);
	Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
	for (int m = 0; m < nMembers; ++m) {
		rel[m] = Eigen::Vector3d(memberPos[3 * m], memberPos[3 * m + 1], memberPos[3 * m + 2]) - X;
		spread += std::pow(memberRadius[m], 3) * rel[m] * rel[m].transpose();  // weights as the members' volumes
	}

	// principal values descending (tension first) and their directions
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (S + S.transpose()));
	const Eigen::Vector3d l  = eig.eigenvalues().reverse();
	Eigen::Matrix3d       n  = eig.eigenvectors().rowwise().reverse();
	const double          tol = kSame * l.cwiseAbs().maxCoeff();
	for (int a = 0; a < 3;) {  // eigenspaces of coinciding values: directions from the members' spread
		int b = a + 1;
		while (b < 3 && l[b - 1] - l[b] <= tol)
			++b;
		if (b - a > 1) n.middleCols(a, b - a) = bySpread(n.middleCols(a, b - a), spread);
		a = b;
	}
	const double mean   = l.sum() / 3;
	const int    planes = (l[1] - mean > tol) ? 2 : 1;  // s2 > 0: n2 is tensile relative to the mean as well

	ClumpSplit out;
	for (int k = 0; k < planes; ++k) {
		const Eigen::Vector3d c = canonical(n.col(k));
		out.normals.insert(out.normals.end(), {c[0], c[1], c[2]});
	}
	std::vector<long> code(nMembers, 0);
	for (int m = 0; m < nMembers; ++m)
		for (int k = 0; k < planes; ++k)
			if (rel[m].dot(Eigen::Vector3d(out.normals[3 * k], out.normals[3 * k + 1], out.normals[3 * k + 2])) > 0)
				code[m] += 1L << k;
	if (nMembers >= 2 && std::all_of(code.begin(), code.end(), [&](long c) { return c == code[0]; })) {
		// all on one side: halves at the median projection on the first direction along which the members differ
		out.median = true;
		std::vector<int> order(nMembers);
		std::iota(order.begin(), order.end(), 0);
		for (int k = 0; k < 3; ++k) {
			std::vector<double> d(nMembers);
			for (int m = 0; m < nMembers; ++m)
				d[m] = rel[m].dot(n.col(k));
			const auto mm = std::minmax_element(d.begin(), d.end());
			if (*mm.second - *mm.first > 0) {
				std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return d[i] < d[j]; });
				break;
			}
		}  // members all at one point: split by index
		for (int r = 0; r < nMembers; ++r)
			code[order[r]] = (2 * r < nMembers) ? 0 : 1;
	}
	// pieces numbered by their first member
	std::vector<long> label(4, -1);
	out.piece.resize(nMembers);
	for (int m = 0; m < nMembers; ++m) {
		if (label[code[m]] < 0) label[code[m]] = out.nPieces++;
		out.piece[m] = label[code[m]];
	}
	for (int i = 0; i < nMembers; ++i)
		for (int j = i + 1; j < nMembers; ++j)
			if (out.piece[i] != out.piece[j]) {
				const double dx = memberPos[3 * i] - memberPos[3 * j], dy = memberPos[3 * i + 1] - memberPos[3 * j + 1],
				             dz = memberPos[3 * i + 2] - memberPos[3 * j + 2];  // not via x - X: no cancellation
				if (std::sqrt(dx * dx + dy * dy + dz * dz) < memberRadius[i] + memberRadius[j]) out.pairs.insert(out.pairs.end(), {i, j});
			}
	return out;
}

}  // namespace ballast
