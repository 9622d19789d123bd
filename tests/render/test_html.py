"""render/html.py: the seed exam's HTML key writes its mathematics as MathML, in markup
that is well-formed XML (checked on every run), and a real browser typesets it: a
fraction stacked, a matrix's rows one above the other, a dot above its letter (checked
where a headless Chromium is installed: Debian's chromium-headless-shell)."""

from __future__ import annotations

import json
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import SEED

BROWSERS = ("chromium-headless-shell", "chromium", "chromium-browser", "google-chrome")


@pytest.fixture(scope="module")
def key(tmp_path_factory):
    """The seed exam's HTML key, without pictures (they are test_key.py's)."""
    path = tmp_path_factory.mktemp("html") / "key.html"
    result = CliRunner().invoke(main, ["key", str(SEED), "-o", str(path), "--no-figures", "--quiet"])
    assert result.exit_code == 0, result.output
    return path


def test_the_key_is_well_formed_xml_with_mathml(key) -> None:
    root = ET.parse(key).getroot()  # raises on markup that is not well-formed
    maths = root.findall(".//math")
    assert len(maths) > 100
    assert all(m.get("displaystyle") == "true" for m in maths)
    for kind in ("mfrac", "msqrt", "mtable", "mover"):  # fractions, roots, matrices, dots
        assert root.find(f".//{kind}") is not None, kind
    boxed = root.findall(".//span[@class='result']/math")
    assert boxed and len(boxed) < len(maths)


def test_no_math_is_left_as_plain_text(key) -> None:
    """Every .math block holds a <math> element, nothing else."""
    root = ET.parse(key).getroot()
    blocks = root.findall(".//div[@class='math']")
    assert blocks and all(b.find("math") is not None or b.find("span/math") is not None for b in blocks)


def _browser() -> str:
    found = next((b for b in map(shutil.which, BROWSERS) if b), None)
    if found is None:
        pytest.skip("no headless Chromium installed (Debian/Ubuntu: apt install chromium-headless-shell)")
    return found


# Measured in the page by the browser's own layout, written into the title for --dump-dom.
PROBE = """<script>
const box = e => e.getBoundingClientRect();
const frac = document.querySelector('mfrac'), row = document.querySelectorAll('mtable')[0].querySelectorAll('mtr');
const over = document.querySelector('mover');
document.title = JSON.stringify({
  fraction_stacked: box(frac.children[0]).bottom <= box(frac.children[1]).top + 1,
  rows_stacked: box(row[0]).bottom <= box(row[1]).top + 1,
  dot_above: box(over.children[1]).top < box(over.children[0]).top,
  math_display: getComputedStyle(document.querySelector('math')).display,
});
</script>"""


def test_a_browser_typesets_the_mathematics(key, tmp_path) -> None:
    browser = _browser()
    page = tmp_path / "probe.html"
    page.write_text(key.read_text(encoding="utf-8").replace("</body>", PROBE + "</body>"), encoding="utf-8")
    done = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", f"--user-data-dir={tmp_path / 'profile'}",
                           "--virtual-time-budget=5000", "--dump-dom", page.as_uri()],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    title = done.stdout.split("<title>", 1)[1].split("</title>", 1)[0]
    import html

    measured = json.loads(html.unescape(title))
    assert measured == {"fraction_stacked": True, "rows_stacked": True, "dot_above": True,
                        "math_display": "math"}, measured  # MathML Core's own display type
