"""docs/oedometer.md's parameter table names every declared parameter once and quotes no defaults (they
are in docs/parameters.md, generated from the declarations: a default stated twice went stale)."""
import os
import re

from ballast.oedometer.parameters import PARAMS

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def table():
    with open(os.path.join(ROOT, 'docs', 'oedometer.md')) as fh:
        text = fh.read()
    start = text.index('| group | parameters (defaults')
    return text[start:text.index('\n\n', start)]


def test_every_parameter_is_in_the_table_once():
    names = re.findall(r'`(\w+)`', table())
    assert sorted(names) == sorted(set(names)) and sorted(set(PARAMS) - set(names)) == []


def test_no_default_is_quoted_beside_a_name():
    assert re.findall(r'`\w+` \(', table()) == []
