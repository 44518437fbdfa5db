"""``yade -n -x scripts/single_particle.py [--name value ...]``: one single-particle test, every parameter
by name (or a yade-batch row), checked before any work. ``scripts/single_particle.py calibrate CSV``:
ft0, m and the Weibull modulus fitted to measured strengths (plain python3; ``--confirm`` inside yade
simulates the fitted model at the measured diameters and fits it again)."""
import sys

from ...params import ParamError
from .. import commandline
from . import calibration
from .declaration import DECLARATION

PROG = 'yade -n -x scripts/single_particle.py'


def runParser():
    ap = commandline.OneLineParser('single_particle.py', DECLARATION.params, prog=PROG, description=(
        'The single-particle crushing test: grains between platens until each first crushes, their '
        'strengths and Weibull statistics (docs/calibration.md). Every parameter can also be a yade-batch '
        'table column. To calibrate from measured strengths: scripts/single_particle.py calibrate CSV.'))
    return commandline.addParameters(ap, DECLARATION.params)


def readParams(argv):
    """defaults <- yade-batch table row <- command line, all checked (experiments.commandline.readParams)."""
    return commandline.readParams(runParser(), argv, DECLARATION)


def calibrateParser():
    ap = commandline.OneLineParser('single_particle.py calibrate', {}, prog='scripts/single_particle.py calibrate',
                                   description=calibration.__doc__.split('\n\n')[0])
    ap.add_argument('csv', help='measured strengths: a diameter column (diameter [m] or diameter_mm) and a force '
                                'column (force [N] or force_kN), a row per grain')
    ap.add_argument('--criterion', default='vonMises', help="the model's criterion (default vonMises)")
    ap.add_argument('--out', default='calibration', help='where calibration.json and calibration.table go')
    ap.add_argument('--confirm', action='store_true', help='inside yade: simulate the fitted model at the measured '
                                                           'diameters and fit it again')
    return ap


def calibrate(argv):
    a = calibrateParser().parse_args(argv)
    try:
        d, force = calibration.readMeasured(a.csv)
        fit = calibration.calibrate(d, force, a.criterion)
    except (calibration.CalibrationError, ParamError, ValueError) as e:
        sys.stderr.write('single_particle.py calibrate: %s\n' % e)
        return 2
    files = calibration.write(fit, a.out)
    print('%d grains, %s: ft0 = %.4g Pa m^m [%.4g, %.4g], m = %.3f [%.3f, %.3f], Weibull modulus %.3f [%.3f, %.3f]' % (
        fit['n'], fit['criterion'], fit['ft0'], fit['ft0Low'], fit['ft0High'], fit['m'], fit['mLow'], fit['mHigh'],
        fit['weibullModulus'], fit['weibullModulusLow'], fit['weibullModulusHigh']))
    print('at the grains\' size, r = %.4g mm: f_t = ft0 / r^m = %.4g Pa [%.4g, %.4g] (ft0 is f_t at r = 1 m; its interval '
          'is wide where m is uncertain)' % (1e3 * fit['rRef'], fit['ftRef'], fit['ftRefLow'], fit['ftRefHigh']))
    print('wrote %s; the oedometer with it: yade -n -x scripts/oedometer.py %s' % (
        ', '.join(files), calibration.commandLine(fit)))
    if a.confirm:
        from .experiment import SingleParticle
        test = SingleParticle(diameters=list(d), results=a.out, runId='confirm', progress=60,
                              **calibration.modelParameters(fit))
        s = test.run()
        crushed = test.table()
        crushed = crushed[crushed.crushed]
        again = calibration.calibrate(crushed.diameter.to_numpy(), crushed.force.to_numpy(), fit['criterion'],
                                      rRef=fit['rRef'])
        inside = fit['ftRefLow'] <= again['ftRef'] <= fit['ftRefHigh']
        print('simulated at the measured diameters (%d of %d crushed): ft0 = %.4g, m = %.3f, Weibull modulus %.3f; '
              'at r = %.4g mm f_t = %.4g Pa, %s the measured fit\'s interval [%.4g, %.4g]: %s' % (
                  s['nCrushed'], s['n'], again['ft0'], again['m'], again['weibullModulus'], 1e3 * fit['rRef'],
                  again['ftRef'], 'inside' if inside else 'outside', fit['ftRefLow'], fit['ftRefHigh'],
                  'confirmed' if inside else 'not confirmed'))
    return 0


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ['calibrate']:
        return calibrate(argv[1:])
    from yade import utils

    def cls():
        from .experiment import SingleParticle
        return SingleParticle
    test = commandline.experiment(runParser(), argv, DECLARATION, cls)
    test.run()
    utils.waitIfBatch()
    return 0
