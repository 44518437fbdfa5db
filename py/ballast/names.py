"""Names and labels shared by the oedometer and the study runner (no YADE needed): both name a run's
directory with :func:`runDirName`, so that the study finds the run where the oedometer wrote it,
and write durations with :func:`fmtTime`."""
import hashlib
import math

# Longest directory name [bytes]; file systems allow 255, a suffix ('.1', '.tmp') must still fit.
MAX_BYTES = 180


def runDirName(s):
    """A run id as a directory name: characters other than alphanumerics and ._=,+- become _,
    leading and trailing dots are stripped ('run' if nothing is left). A name longer than
    MAX_BYTES (in UTF-8) is cut and ends with 8 hex digits of its sha1, so long descriptions stay
    distinct. Applying it twice changes nothing."""
    s = ''.join(c if (c.isalnum() or c in '._=,+-') else '_' for c in s).strip('.') or 'run'
    b = s.encode()
    if len(b) <= MAX_BYTES:
        return s
    return b[:MAX_BYTES - 10].decode(errors='ignore') + '_' + hashlib.sha1(b).hexdigest()[:8]


def fmtTime(s):
    """A duration [s] as 42s, 3m05s or 2h07m; '?' if unknown (None, NaN, inf)."""
    if s is None or not math.isfinite(s):
        return '?'
    s = int(round(s))
    if s >= 3600:
        return '%dh%02dm' % (s // 3600, (s % 3600) // 60)
    return '%dm%02ds' % (s // 60, s % 60) if s >= 60 else '%ds' % s
