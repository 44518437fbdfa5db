"""Tests of pkg/python/bind_Types.cpp: a sequence of 3x3 matrices (YADE's utils.bodyStressTensors(), minieigen
Matrix3 read in place as ballast::Mat3) as an (N,3,3) array. Outside YADE there is no minieigen: the NumPy path."""
import numpy as np
import pytest

import ballast._ballast as B


def test_lists_tuples_and_arrays_of_matrices_in_row_major_order():
    a = np.arange(18.0).reshape(2, 3, 3)
    for form in (list(a), tuple(a), a, [m.tolist() for m in a]):
        out = B.matricesToArray(form)
        assert out.shape == (2, 3, 3)
        np.testing.assert_array_equal(out, a)
    assert out[1, 0, 2] == 11.0  # row-major: matrix 1, row 0, column 2 = 9 + 2
    assert B.matricesToArray([]).shape == (0, 3, 3)


def test_no_minieigen_outside_yade():
    assert B._fastMatrixPath(np.eye(3)) is False
    assert B._fastMatrixPath(None) is False


@pytest.mark.parametrize('call,exc,message', [
    (lambda: B.matricesToArray(5), TypeError, 'matrices: expected a sequence of 3x3 matrices, got int'),
    (lambda: B.matricesToArray([np.eye(3), np.full((3, 3), np.nan)]), ValueError,
     'matrices[1]: expected finite numbers, got nan at flat index 0'),
    (lambda: B.matricesToArray([np.eye(2)]), TypeError, 'matrices[0]: expected a 3x3 matrix, got shape (2,2)'),
])
def test_bad_input_names_the_matrix(call, exc, message):
    with pytest.raises(exc) as e:
        call()
    assert str(e.value) == message
