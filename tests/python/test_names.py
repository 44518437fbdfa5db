"""Tests of ballast.names: the run directory names and duration labels the oedometer and the study
runner share."""
from ballast.names import MAX_BYTES, fmtTime, runDirName


def test_run_dir_name_keeps_the_allowed_characters():
    assert runDirName('seed=1,f=0.5,pattern=planar4') == 'seed=1,f=0.5,pattern=planar4'
    assert runDirName("a b/c'd:e+f-g") == 'a_b_c_d_e+f-g'
    assert runDirName('..hidden.') == 'hidden' and runDirName('...') == 'run' and runDirName('') == 'run'


def test_long_names_are_cut_distinct_and_stable():
    a, b = 'x' * 300 + 'a', 'x' * 300 + 'b'
    assert len(runDirName(a).encode()) <= MAX_BYTES and runDirName(a) != runDirName(b)
    assert len(runDirName('é' * 200).encode()) <= MAX_BYTES  # bytes, not characters
    for s in (a, 'é' * 200, "a b/c'd", '.x.'):
        assert runDirName(runDirName(s)) == runDirName(s)  # the oedometer may apply it again


def test_durations():
    assert [fmtTime(s) for s in (None, float('nan'), 0.4, 59.6, 61, 3599, 3600, 7620)] == [
        '?', '?', '0s', '1m00s', '1m01s', '59m59s', '1h00m', '2h07m']
