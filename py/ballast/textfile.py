"""The one strict reader of the text files users give (tables, load histories, measured curves): UTF-8 text or
NotText naming the file and the first byte that is not (a binary file, another encoding, a NUL)."""


class NotText(ValueError):
    """A file given as text is not: its message names the file and the offending byte."""


def read(path):
    """The file's text [str]; NotText if it is not UTF-8 text; OSError as open() raises it."""
    with open(path, 'rb') as fh:
        data = fh.read()
    try:
        text = data.decode('utf-8')
    except UnicodeDecodeError as e:
        raise NotText('%s: not a text file: byte %d (0x%02x) is not UTF-8 (a binary file or another encoding?)' % (
            path, e.start, data[e.start])) from None
    if '\0' in text:
        raise NotText('%s: not a text file: it holds a NUL byte at %d (a binary file?)' % (path, text.index('\0')))
    return text
