"""The drained monotonic compression of the triaxial test (docs/triaxial.md, "Monotonic compression"): after the
consolidation to p', the top platen driven down at a constant axial strain rate (displacement control, as a
laboratory press), the membrane holding p', until the axial strain reaches maxAxialStrain. What it measures: the
deviator the grains carry against the axial strain, the volumetric strain (contraction then dilation), the peak
deviator and its mobilised friction angle, sin phi = 3 eta / (6 + eta) with eta = q / p, p = p' + q / 3 (triaxial
compression), and the dilatancy angle there, sin psi = -s / (2 - s) with s = d eps_v / d eps_a (compression
positive). Plain NumPy but for the YADE reads of :func:`row`."""
import math

import numpy as np

COLUMNS = ('t', 'axialStrain', 'volumetricStrain', 'q', 'p', 'stressRatio', 'nCrushed', 'nAbraded', 'inertialNumber')
ROWS = 400   # [-] rows of monotonic.csv over the test


def frictionAngle(q, p):
    """The mobilised friction angle [deg] of triaxial compression at deviator q and mean stress p [Pa]:
    sin phi = 3 eta / (6 + eta), eta = q / p (Mohr-Coulomb's q/p = 6 sin phi / (3 - sin phi))."""
    eta = q / p
    return math.degrees(math.asin(3 * eta / (6 + eta)))


def dilatancyAngle(s):
    """The dilatancy angle [deg] for s = d eps_v / d eps_a (compression positive: s < 0 dilates):
    sin psi = -s / (2 - s), from d eps_v = d eps_a + 2 d eps_r and sin psi = -(d eps_a + 2 d eps_r) / (d eps_a - 2 d eps_r)."""
    return math.degrees(math.asin(max(-1.0, min(1.0, -s / (2 - s)))))


def peak(rows):
    """The peak of a test's rows (COLUMNS, a list or an array): {qPeak [Pa], axialStrainAtPeak, volumetricStrainAtPeak,
    pAtPeak [Pa], frictionAnglePeak [deg], dilatancyAngleAtPeak [deg] (the slope of eps_v against eps_a over the rows
    within 1 % of axial strain of the peak, a least-squares line), volumetricStrainEnd, axialStrainEnd}."""
    a = np.asarray(rows, dtype=float)
    c = dict(zip(COLUMNS, a.T))
    k = int(np.argmax(c['q']))
    near = np.abs(c['axialStrain'] - c['axialStrain'][k]) <= 0.01
    s = float(np.polyfit(c['axialStrain'][near], c['volumetricStrain'][near], 1)[0]) if near.sum() >= 2 else math.nan
    return {'qPeak': float(c['q'][k]), 'axialStrainAtPeak': float(c['axialStrain'][k]),
            'volumetricStrainAtPeak': float(c['volumetricStrain'][k]), 'pAtPeak': float(c['p'][k]),
            'frictionAnglePeak': frictionAngle(c['q'][k], c['p'][k]),
            'dilatancyAngleAtPeak': dilatancyAngle(s) if math.isfinite(s) else math.nan,
            'axialStrainEnd': float(c['axialStrain'][-1]), 'volumetricStrainEnd': float(c['volumetricStrain'][-1])}


def figure(rows, path, title):
    """monotonic.png: the deviator against the axial strain, the volumetric strain against it."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    a = np.asarray(rows, dtype=float)
    c = dict(zip(COLUMNS, a.T))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.2))
    ax1.plot(100 * c['axialStrain'], c['q'] / 1e3, '-')
    ax1.set_xlabel('axial strain [%]')
    ax1.set_ylabel('deviator stress q carried by the grains [kPa]')
    ax2.plot(100 * c['axialStrain'], 100 * c['volumetricStrain'], '-')
    ax2.set_xlabel('axial strain [%]')
    ax2.set_ylabel('volumetric strain [%] (compression positive)')
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
