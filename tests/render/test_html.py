"""render/html.py: the seed exam's HTML key writes its mathematics as MathML, in markup
that is well-formed XML (checked on every run), and a real browser typesets it as a
reader sees it (checked where a headless Chromium is installed: Debian's chromium or
chromium-headless-shell): a fraction stacked, a matrix's rows one above the other, no
scroll widget beside an equation that fits, π upright, and a rate's dot standing clear
above its letter at text size — measured in a screenshot, row by row of pixels, since
a dot lowered onto the letter's top stroke is still "above" it by the layout's boxes."""

from __future__ import annotations

import json
import re
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
const blocks = [...document.querySelectorAll('div.math')];
const pis = [...document.querySelectorAll('mi')].filter(e => e.textContent === 'π');
document.title = JSON.stringify({
  fraction_stacked: box(frac.children[0]).bottom <= box(frac.children[1]).top + 1,
  rows_stacked: box(row[0]).bottom <= box(row[1]).top + 1,
  dot_above: box(over.children[1]).top < box(over.children[0]).top,
  math_display: getComputedStyle(document.querySelector('math')).display,
  // a scroll bar takes width from the block: offsetWidth > clientWidth where one shows
  scroll_widgets: blocks.filter(b => b.scrollWidth <= b.clientWidth && b.offsetWidth > b.clientWidth).length,
  pi_upright: pis.length > 0 && pis.every(e => getComputedStyle(e).textTransform === 'none'),
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
                        "math_display": "math",  # MathML Core's own display type
                        "scroll_widgets": 0, "pi_upright": True}, measured


def _headless(browser: str, tmp_path, *args: str) -> None:
    done = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                           "--disable-background-networking", "--disable-component-update", "--disable-sync",
                           f"--user-data-dir={tmp_path / 'profile'}", *args],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]


def ink_runs(png) -> list[tuple[int, int]]:
    """The runs of consecutive pixel rows that hold ink (darker than mid-grey), top first."""
    from matplotlib.image import imread

    image = imread(str(png))
    rows = (image[..., :3].mean(axis=2) < 0.5).any(axis=1)
    runs, start = [], None
    for y, inked in enumerate(list(rows) + [False]):
        if inked and start is None:
            start = y
        elif not inked and start is not None:
            runs.append((start, y))
            start = None
    return runs


@pytest.mark.parametrize("dots", ["\u02d9", "\u00a8"], ids=["one dot", "two dots"])
def test_a_rate_dot_stands_clear_above_its_letter_at_text_size(key, tmp_path, dots) -> None:
    """The key's own markup for θ̇ (θ̈), alone on a page with the key's style, at text
    size, screenshotted: the top run of ink rows is the dot, small, with blank rows
    between it and the letter (with accent="true" Chromium set it on the top stroke)."""
    browser = _browser()
    text = key.read_text(encoding="utf-8")
    over = next(m for m in re.findall(r"<mover[^>]*>.*?</mover>", text) if f"<mo>{dots}</mo>" in m)
    head = text.split("<body", 1)[0]
    page = tmp_path / "dot.html"
    page.write_text(f'{head}<body style="margin:0;background:#fff"><div class="math">'
                    f'<math displaystyle="true">{over}</math></div></body></html>', encoding="utf-8")
    shot = tmp_path / "dot.png"
    _headless(browser, tmp_path, "--force-device-scale-factor=3", "--window-size=160,80",
              f"--screenshot={shot}", page.as_uri())
    runs = ink_runs(shot)
    assert len(runs) >= 2, runs  # the dot and the letter apart
    (dot_top, dot_bottom), (letter_top, letter_bottom) = runs[0], runs[-1]
    assert dot_bottom - dot_top < (letter_bottom - dot_top) / 3, runs  # the top run is a dot, not the letter
    assert letter_top - dot_bottom >= 2, runs  # rows of white between: the dot stands clear
