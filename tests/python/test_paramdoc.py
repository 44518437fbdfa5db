"""ballast.paramdoc: docs/parameters.md is the page the declarations generate (no YADE)."""
import os

from ballast import paramdoc
from ballast.oedometer.parameters import PARAMS
from ballast.engineparams import ABRASION, CRUSH, PERIODIC

DOC = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), 'docs',
                   'parameters.md')


def test_page_is_up_to_date():
    with open(DOC) as fh:
        assert fh.read() == paramdoc.page(), 'regenerate: python3 -m ballast.paramdoc > docs/parameters.md'


def test_every_parameter_is_listed_with_its_range():
    page = paramdoc.page()
    for table in (CRUSH, ABRASION, PERIODIC, PARAMS):
        for name, p in table.items():
            assert '| `%s` | %s | %s |' % (name, p.unit, p.allowed.replace('|', '\\|')) in page, name
