#!/usr/bin/env python3
"""The workflow report as a researcher sees it: headless Chromium at 1280x800 (issue 16).

Issue 16 asks for reports a researcher can read. This test opens report.html in headless
Chromium (Selenium + chromedriver, Debian packages chromium, chromium-driver, python3-selenium)
with a 1280x800 CSS-pixel viewport and checks what a reader would run into:

  a. images: every <img> is loaded (complete, naturalWidth > 0), none shows as broken;
  b. links: every relative link (and file: link) names a file or folder that exists, relative to
     the page's folder; a same-page #fragment names an element on the page. http(s) and mailto
     links are not followed;
  c. tall rows: no table row is taller than the viewport (800 px), so a row never has to be
     scrolled through;
  d. link walls: a table cell holding links keeps them on one line (the tops of all its links'
     line boxes lie within one line height);
  e. figure text: no gnuplot enhanced-text markup ("{/", "_{", "^{", "@") in the text of the SVG
     figures, no word split by a one-letter sub/superscript (gnuplot reads "syamlal_algebraic"
     as "syamlal" + subscript "a" + "lgebraic"), and no such markup in the page's own text;
  f. first screen: section#findings holds a .headline, and a div.figures.first-screen holds
     images; at scroll position 0 the first headline and every one of those images lie wholly
     inside the viewport and are loaded;
  g. width: the page does not scroll sideways (scrollWidth <= the viewport's client width, i.e.
     1280 minus a vertical scrollbar if one is shown).

Every failure is collected and printed with what failed and where; exit 1 if there is any.
Exit 77 (ctest: skipped) when Chromium, chromedriver or Selenium is missing, unless
GRAINBRIDGE_REQUIRE_BROWSER=1 (scripts/test.sh sets it, having installed them): then exit 1.

With --bed-compare it also checks a comparison of bed runs (a bed_compare stage, issue 62):

  h. one colour per run: the s_p and mean-height-against-time figures each draw at least as many
     distinct line colours (grid, frame and black text aside) as the comparison has runs;
  i. runs by name: the time-averaged height figure names every run along x (its legend's names)
     and has no numeric "run (row of the table)" axis;
  j. s_p named for what it is (a binary bed's page): the findings table heads it "segregation
     percentage s_p [%]", not a bare fraction's name, and its figure's axis reads the same.

Without --report it runs --config (default configs/quickstart.json) into --work (emptied first):
`grainbridge run` then `grainbridge report`, whose first .html line on stdout is the report's
path. With --report it checks that file as it is. --screenshot saves the first screen (1280x800
PNG; --full-page: the whole page), pass or fail.
"""
import argparse
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.parse
import urllib.request
import xml.etree.ElementTree as ET

SKIP = 77
VIEWPORT = (1280, 800)
PIXEL_SLACK = 0.5  # sub-pixel layout: a rect edge at 800.4 still counts as inside 800
SYSTEM_PYTHON = "/usr/bin/python3"  # Debian's python3-selenium lives in its dist-packages
CHROMIUM_CANDIDATES = ("/usr/lib/chromium/chromium", "chromium", "chromium-browser", "google-chrome")
CHROMEDRIVER_CANDIDATES = ("/usr/lib/chromium/chromedriver", "chromedriver")
CHROMIUM_FLAGS = (
    "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--disable-dev-shm-usage", "--window-size=1280,800",
)
GNUPLOT_MARKUP = ("{/", "_{", "^{", "@")
PAGE_MARKUP = ("{/", "_{", "^{")
IGNORED_SCHEMES = ("http", "https", "mailto")


# ---------------------------------------------------------------- prerequisites

def import_selenium():
    """Selenium's webdriver module, or None. A python3 without it (pyenv, a venv) hands over to
    Debian's /usr/bin/python3 once, which is where the python3-selenium package installs it."""
    try:
        from selenium import webdriver
        return webdriver
    except ImportError:
        pass
    here = os.path.realpath(sys.executable)
    if (not os.environ.get("REPORT_BROWSER_REEXEC") and os.path.exists(SYSTEM_PYTHON)
            and os.path.realpath(SYSTEM_PYTHON) != here):
        os.environ["REPORT_BROWSER_REEXEC"] = "1"
        sys.stdout.flush()
        os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON, *sys.argv])
    return None


def find_program(candidates):
    for name in candidates:
        path = shutil.which(name)
        if path:
            return path
    return None


def prerequisites():
    """(webdriver module, chromium path, chromedriver path), or exit 77 saying what is missing."""
    webdriver = import_selenium()
    chromium = find_program(CHROMIUM_CANDIDATES)
    chromedriver = find_program(CHROMEDRIVER_CANDIDATES)
    missing = [what for what, found in (("Selenium for Python (python3-selenium)", webdriver),
                                        ("Chromium (chromium)", chromium),
                                        ("chromedriver (chromium-driver)", chromedriver)) if not found]
    if missing:
        # scripts/test.sh has just installed them: there a missing piece is a failure, not a skip.
        required = os.environ.get("GRAINBRIDGE_REQUIRE_BROWSER") == "1"
        print(f"report_browser: {'FAILED' if required else 'skipped'}, missing {', '.join(missing)}; "
              "scripts/install-deps.sh --tests installs them")
        sys.exit(1 if required else SKIP)
    return webdriver, chromium, chromedriver


# ---------------------------------------------------------------- the report

def produce_report(grainbridge, repo, work, config_name):
    """Run the config into an empty `work` and write its report; return report.html's path."""
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    config = str(repo / "configs" / config_name)
    try:
        subprocess.run([grainbridge, "-q", "run", config, "--workdir", str(work)], cwd=work, check=True)
        out = subprocess.run([grainbridge, "report", config, "--workdir", str(work)], cwd=work, check=True,
                             stdout=subprocess.PIPE, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as error:
        sys.exit(f"report_browser: {config_name} did not run through: {error}")
    for line in out.splitlines():
        if line.strip().endswith(".html"):
            return pathlib.Path(line.strip())
    sys.exit(f"report_browser: `grainbridge report` printed no .html path:\n{out}")


# ---------------------------------------------------------------- the browser

def start_browser(webdriver, chromium, chromedriver, profile):
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for flag in CHROMIUM_FLAGS:
        options.add_argument(flag)
    options.add_argument(f"--user-data-dir={profile}")
    driver = webdriver.Chrome(service=Service(executable_path=chromedriver), options=options)
    driver.set_page_load_timeout(120)
    # In new headless mode --window-size is the outer window: the viewport comes out shorter
    # (1280x657 here). Pin the CSS viewport itself.
    width, height = VIEWPORT
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
    return driver


def open_page(driver, page):
    driver.get(page.as_uri())  # returns after the load event: images have loaded or failed
    driver.execute_script("window.scrollTo(0, 0)")
    size = driver.execute_script("return [window.innerWidth, window.innerHeight]")
    if tuple(size) != VIEWPORT:
        sys.exit(f"report_browser: viewport is {size[0]}x{size[1]}, not {VIEWPORT[0]}x{VIEWPORT[1]}")


# Describes where an element sits: the table's caption or nearest preceding heading, and the
# row's number (1 = first row of the table, header included) and first cell. Prepended to the
# scripts below.
JS_WHERE = r"""
const clip = (s, n = 60) => { s = (s || '').replace(/\s+/g, ' ').trim(); return s.length > n ? s.slice(0, n) + '...' : s; };
const headingOf = el => {
  const table = el.closest('table');
  const cap = table && table.querySelector(':scope > caption');
  if (cap) return clip(cap.innerText);
  const h = document.evaluate('preceding::*[self::h1 or self::h2 or self::h3 or self::h4 or self::h5 or self::h6][1]',
                              table || el, null, XPathResult.FIRST_ORDERED_NODE_TYPE, null).singleNodeValue;
  return h ? clip(h.innerText) : '(no heading)';
};
const rowOf = el => { const r = el.closest('tr'); if (!r) return '(no row)';
                      return `row ${r.rowIndex + 1} "${r.cells.length ? clip(r.cells[0].innerText, 40) : ''}"`; };
const where = el => `table "${headingOf(el)}", ${rowOf(el)}`;
const box = r => ({top: r.top, bottom: r.bottom, left: r.left, right: r.right, width: r.width, height: r.height});
"""


def js(driver, body):
    return driver.execute_script(JS_WHERE + body)


# ---------------------------------------------------------------- the checks
# Each returns (number of things checked, list of failure messages).

def check_images(driver):
    images = js(driver, """
      return Array.from(document.images).map(i => ({src: i.getAttribute('src') || '', url: i.src,
                                                    complete: i.complete, naturalWidth: i.naturalWidth}));""")
    failures = [f"a. broken image: <img src=\"{i['src']}\"> (complete={i['complete']}, naturalWidth={i['naturalWidth']})"
                for i in images if not (i["complete"] and i["naturalWidth"] > 0)]
    return len(images), failures


def link_target(page, href):
    """The file a link names, or None when it is not a local link (http, https, mailto, ...)."""
    parts = urllib.parse.urlsplit(href)
    if parts.scheme.lower() == "file":
        return pathlib.Path(urllib.request.url2pathname(parts.path))
    if parts.scheme:
        return None
    path = urllib.parse.unquote(parts.path)
    if not path:
        return page
    return pathlib.Path(path) if path.startswith("/") else page.parent / path


def check_links(driver, page):
    links = js(driver, """
      const found = id => !id || !!document.getElementById(id) || document.getElementsByName(id).length > 0;
      return Array.from(document.querySelectorAll('a[href]')).map(a => {
        const href = a.getAttribute('href');
        const frag = href.startsWith('#') ? decodeURIComponent(href.slice(1)) : null;
        return {href: href, text: clip(a.innerText, 40), inTable: !!a.closest('table'),
                where: a.closest('table') ? where(a) : '', fragmentFound: frag === null ? true : found(frag)};
      });""")
    checked, failures = 0, []
    for link in links:
        scheme = urllib.parse.urlsplit(link["href"]).scheme.lower()
        if scheme in IGNORED_SCHEMES:
            continue
        target = link_target(page, link["href"])
        if target is None:
            continue
        checked += 1
        place = f" in {link['where']}" if link["inTable"] else ""
        if not target.exists():
            failures.append(f"b. broken link: href=\"{link['href']}\" (text \"{link['text']}\"){place}: "
                            f"{target} does not exist")
        elif not link["fragmentFound"]:
            failures.append(f"b. broken link: href=\"{link['href']}\"{place}: no element with that id on the page")
    return checked, failures


def check_row_heights(driver):
    rows = js(driver, """
      return Array.from(document.querySelectorAll('tr')).map(r => ({where: where(r),
                                                                   height: r.getBoundingClientRect().height}));""")
    limit = VIEWPORT[1]
    failures = [f"c. table row taller than the screen: {r['height']:.0f} px > {limit} px, {r['where']}"
                for r in rows if r["height"] > limit + PIXEL_SLACK]
    return len(rows), failures


def check_link_lines(driver):
    cells = js(driver, """
      return Array.from(document.querySelectorAll('td, th')).map(c => {
        const links = Array.from(c.querySelectorAll('a')).filter(a => a.closest('td, th') === c);
        if (!links.length) return null;
        const tops = links.flatMap(a => Array.from(a.getClientRects()).filter(r => r.width > 0 || r.height > 0)
                                                                       .map(r => r.top));
        const style = getComputedStyle(c);
        const fontSize = parseFloat(style.fontSize);
        const lineHeight = style.lineHeight === 'normal' ? 1.5 * fontSize : parseFloat(style.lineHeight);
        return {where: where(c), links: links.length, tops: tops, lineHeight: lineHeight};
      }).filter(c => c && c.tops.length);""")
    failures = []
    for cell in cells:
        spread = max(cell["tops"]) - min(cell["tops"])
        if spread >= cell["lineHeight"]:
            lines = round(spread / cell["lineHeight"]) + 1
            failures.append(f"d. links wrap over ~{lines} lines in one cell ({cell['links']} links), {cell['where']}")
    return len(cells), failures


def svg_files(driver):
    """The SVG files shown by <img> elements, each once: {path: src as written}."""
    images = driver.execute_script(
        "return Array.from(document.images).map(i => [i.getAttribute('src') || '', i.src]);")
    files = {}
    for src, url in images:
        parts = urllib.parse.urlsplit(url)
        if parts.scheme == "file" and parts.path.lower().endswith(".svg"):
            files.setdefault(pathlib.Path(urllib.request.url2pathname(parts.path)), src)
    return files


def local_name(element):
    return element.tag.rsplit("}", 1)[-1]


def font_size(tspan):
    try:
        return float(tspan.get("font-size", "").removesuffix("px"))
    except ValueError:
        return None


def shift(tspan):
    """A tspan's vertical shift in px (its dy), 0 when it has none."""
    try:
        return float(tspan.get("dy", "0").removesuffix("px"))
    except ValueError:
        return 0.0


def enhanced_text_reading(text_element):
    """The label as it was probably written when gnuplot's enhanced text broke a word with a
    one-character sub/superscript, else None. gnuplot reads "p_shear" as "p" + subscript "s" +
    "hear": a shifted (dy), smaller tspan holding one letter or digit, glued to letters on both
    sides. A meant exponent such as "d^2 gammadot" is not glued to a letter on its right."""
    tspans = [t for t in text_element.iter() if local_name(t) == "tspan"]
    sizes = [s for s in map(font_size, tspans) if s is not None]
    largest = max(sizes, default=None)

    def smaller_and_shifted(tspan):
        size = font_size(tspan)
        return shift(tspan) != 0 and size is not None and size < largest

    broken = any(smaller_and_shifted(mid) and len(mid.text or "") == 1 and (mid.text or "").isalnum()
                 and (before.text or "")[-1:].isalpha() and (after.text or "")[:1].isalpha()
                 for before, mid, after in zip(tspans, tspans[1:], tspans[2:]))
    if not broken:
        return None
    # SVG's y axis points down: a positive dy is a subscript.
    return "".join(("_" if shift(t) > 0 else "^") + (t.text or "") if smaller_and_shifted(t) else (t.text or "")
                   for t in tspans).strip()


def check_svg(path, src):
    failures = []
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as error:
        return [f"e. figure {src}: cannot read the SVG ({error})"]
    for text in (t for t in root.iter() if local_name(t) == "text"):
        content = "".join(text.itertext())
        for markup in GNUPLOT_MARKUP:
            if markup in content:
                failures.append(f"e. figure {src}: text \"{content.strip()}\" shows gnuplot markup \"{markup}\"")
        meant = enhanced_text_reading(text)
        if meant:
            failures.append(f"e. figure {src}: text reads \"{content.strip()}\" with a one-letter sub/superscript "
                            f"inside a word: gnuplot enhanced text on \"{meant}\"?")
    return failures


def check_figure_text(driver):
    files = svg_files(driver)
    failures = [f for path, src in files.items() for f in check_svg(path, src)]
    page_text = driver.execute_script("return document.body ? document.body.innerText : ''")
    inline_svg = driver.execute_script(
        "return Array.from(document.querySelectorAll('svg text')).map(t => t.textContent).join('\\n')")
    for markup in PAGE_MARKUP:
        for name, text in (("page text", page_text), ("inline SVG text", inline_svg)):
            at = text.find(markup)
            if at >= 0:
                context = " ".join(text[max(0, at - 30):at + 30].split())
                failures.append(f"e. {name} shows markup \"{markup}\": ...{context}...")
    return len(files), failures


def check_first_screen(driver):
    state = js(driver, """
      window.scrollTo(0, 0);
      const findings = document.querySelector('section#findings');
      const headline = findings && findings.querySelector('.headline');
      const figures = document.querySelector('div.figures.first-screen');
      return {findings: !!findings, figures: !!figures,
              headline: headline && {text: clip(headline.innerText), rect: box(headline.getBoundingClientRect())},
              images: figures ? Array.from(figures.querySelectorAll('img')).map(i => ({
                src: i.getAttribute('src') || '', loaded: i.complete && i.naturalWidth > 0,
                rect: box(i.getBoundingClientRect())})) : [],
              width: document.documentElement.clientWidth, height: document.documentElement.clientHeight};""")
    width, height = state["width"], state["height"]

    def outside(rect):
        return (rect["top"] < -PIXEL_SLACK or rect["left"] < -PIXEL_SLACK
                or rect["bottom"] > height + PIXEL_SLACK or rect["right"] > width + PIXEL_SLACK)

    def span(rect):
        return (f"x {rect['left']:.0f}..{rect['right']:.0f}, y {rect['top']:.0f}..{rect['bottom']:.0f} "
                f"in a {width}x{height} screen")

    failures = []
    if not state["findings"]:
        failures.append("f. first screen: no section#findings on the page")
    elif not state["headline"]:
        failures.append("f. first screen: section#findings holds no .headline element")
    elif outside(state["headline"]["rect"]):
        failures.append(f"f. first screen: the first headline \"{state['headline']['text']}\" is not wholly "
                        f"visible at the top of the page ({span(state['headline']['rect'])})")
    if not state["figures"]:
        failures.append("f. first screen: no div.figures.first-screen on the page")
    elif not state["images"]:
        failures.append("f. first screen: div.figures.first-screen holds no <img>")
    for image in state["images"]:
        if not image["loaded"]:
            failures.append(f"f. first screen: figure {image['src']} is not loaded")
        if outside(image["rect"]):
            failures.append(f"f. first screen: figure {image['src']} is not wholly visible ({span(image['rect'])})")
    return len(state["images"]), failures


def check_width(driver):
    state = js(driver, """
      const root = document.documentElement, limit = root.clientWidth;
      // How far right an element reaches: its box, or its content when that spills out of it
      // (a <pre> line, a table cell's long word) unless the element scrolls that content itself.
      const reach = e => { const r = e.getBoundingClientRect();
                           const spills = getComputedStyle(e).overflowX === 'visible';
                           return Math.max(r.right, spills ? r.left + e.scrollWidth : r.right); };
      const tooWide = e => e && e !== document.body && reach(e) > limit + 0.5;
      const wide = Array.from(document.body ? document.body.querySelectorAll('*') : [])
        .filter(e => tooWide(e) && !tooWide(e.parentElement))
        .slice(0, 5).map(e => `<${e.tagName.toLowerCase()}${e.id ? '#' + e.id : ''}> reaching ${Math.round(reach(e))} px`
                             + ` under "${headingOf(e)}"`);
      return {scrollWidth: root.scrollWidth, clientWidth: limit, wide: wide};""")
    if state["scrollWidth"] <= state["clientWidth"]:
        return []
    culprits = "; ".join(state["wide"]) or "no single element found"
    return [f"g. the page scrolls sideways: {state['scrollWidth']} px wide in a {state['clientWidth']} px "
            f"viewport; sticking out: {culprits}"]


# Grid, frame, text and background: drawn in every figure, whatever the runs.
NON_DATA_STROKES = {"rgb(221,221,221)", "rgb(68,68,68)", "rgb(0,0,0)", "rgb(255,255,255)"}


def stroke_colours(svg_text):
    """The line colours of a gnuplot SVG, without spaces: {"rgb(0,114,178)", ...}."""
    return {re.sub(r"\s+", "", c) for c in re.findall(r"stroke='(rgb\([^)]*\))'", svg_text)}


def check_bed_compare(driver, page):
    """h-j on the page's bed_compare findings: (runs, failures)."""
    failures = []
    state = js(driver, """
      const imgs = Array.from(document.querySelectorAll('#findings img')).map(i => i.src);
      const heads = Array.from(document.querySelectorAll('#findings table.findings th')).map(t => t.textContent);
      const runs = Array.from(document.querySelectorAll('#findings table.findings tr'))
        .slice(1).map(r => r.cells.length ? r.cells[0].textContent : '');
      return {imgs: imgs, heads: heads, runs: runs};""")
    runs = len(state["runs"])
    svgs = {}
    for url in state["imgs"]:
        parts = urllib.parse.urlsplit(url)
        path = pathlib.Path(urllib.request.url2pathname(parts.path))
        if path.suffix == ".svg":
            svgs[path.name] = path.read_text(encoding="utf-8")
    if runs < 2:
        failures.append(f"h. the findings table shows {runs} run(s); a comparison needs two")
    label = "segregation percentage s_p [%]"
    binary = "segregation_percentage.svg" in svgs  # a binary bed's page; a mono bed has no s_p
    for name in ("segregation_percentage.svg", "mean_height.svg") if binary else ("mean_height.svg",):
        if name not in svgs:
            failures.append(f"h. the findings show no {name}")
            continue
        colours = stroke_colours(svgs[name]) - NON_DATA_STROKES
        if len(colours) < runs:
            failures.append(f"h. {name} draws {len(colours)} line colour(s) ({', '.join(sorted(colours))}) "
                            f"for {runs} runs: one colour per run")
    averaged = svgs.get("mean_height_averaged.svg")
    if averaged is None:
        failures.append("i. the findings show no mean_height_averaged.svg")
    else:
        if "row of the table" in averaged:
            failures.append("i. mean_height_averaged.svg numbers the runs (\"run (row of the table)\")")
        root = ET.fromstring(averaged)
        texts = {"".join(t.itertext()).strip() for t in root.iter() if local_name(t) == "text"}
        # The axis' labels: not a number, not an axis title (a unit in brackets) or the title.
        names = [t for t in texts if t and not t.replace(".", "", 1).lstrip("-").isdigit() and "[" not in t
                 and t not in ("run", "Time-averaged mean particle height")]
        unnamed = [label for label in state["runs"] if not any(n in label for n in names)]
        if unnamed:
            failures.append(f"i. mean_height_averaged.svg names no part of {', '.join(unnamed)} along x "
                            f"(its labels: {sorted(names)})")
    if binary and label not in state["heads"]:
        failures.append(f"j. the findings table has no column \"{label}\" (its heads: {state['heads']})")
    if binary and label not in svgs.get("segregation_percentage.svg", ""):
        failures.append(f"j. segregation_percentage.svg's axis does not read \"{label}\"")
    return runs, failures


def run_checks(driver, page):
    """All checks on the open page: (counts, failures)."""
    images, failures = check_images(driver)
    links, found = check_links(driver, page)
    failures += found
    rows, found = check_row_heights(driver)
    failures += found
    cells, found = check_link_lines(driver)
    failures += found
    svgs, found = check_figure_text(driver)
    failures += found
    first, found = check_first_screen(driver)
    failures += found
    failures += check_width(driver)
    counts = {"images": images, "local links": links, "table rows": rows, "link cells": cells,
              "SVG figures": svgs, "first-screen figures": first}
    return counts, failures


def save_screenshot(driver, path, full_page=False):
    path.parent.mkdir(parents=True, exist_ok=True)
    driver.execute_script("window.scrollTo(0, 0)")
    if full_page:  # the whole page at 1280 px: the viewport stretched to its height (after the checks)
        height = driver.execute_script("return document.documentElement.scrollHeight")
        driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                               {"width": VIEWPORT[0], "height": height, "deviceScaleFactor": 1, "mobile": False})
    if not driver.save_screenshot(str(path)):
        print(f"report_browser: could not save the screenshot {path}", file=sys.stderr)
        return False
    print(f"report_browser: screenshot of the {'whole page' if full_page else 'first screen'} in {path}")
    return True


# ---------------------------------------------------------------- main

def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--grainbridge", help="grainbridge executable")
    parser.add_argument("--repo", type=pathlib.Path, help="source tree (for configs/quickstart.json)")
    parser.add_argument("--work", type=pathlib.Path, help="work folder (emptied) for the quickstart run")
    parser.add_argument("--config", default="quickstart.json",
                        help="the config under configs/ to run (default quickstart.json)")
    parser.add_argument("--bed-compare", action="store_true",
                        help="also check the comparison of bed runs (h-j): for a config with a bed_compare stage")
    parser.add_argument("--report", type=pathlib.Path,
                        help="check this report.html instead of running the quickstart (then the three above are not needed)")
    parser.add_argument("--screenshot", type=pathlib.Path, help="save the first screen (1280x800) as this PNG")
    parser.add_argument("--full-page", action="store_true",
                        help="with --screenshot: the whole page at 1280 px wide, not its first screen")
    args = parser.parse_args()
    if not args.report and not (args.grainbridge and args.repo and args.work):
        parser.error("give --grainbridge, --repo and --work (to run the quickstart), or --report")
    return args


def main():
    args = parse_args()
    webdriver, chromium, chromedriver = prerequisites()
    if args.report:
        page = args.report.resolve()
        if not page.is_file():
            sys.exit(f"report_browser: no report at {page}")
    else:
        page = produce_report(args.grainbridge, args.repo.resolve(), args.work.resolve(), args.config)

    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="report_browser-profile-", ignore_cleanup_errors=True) as profile:
        driver = start_browser(webdriver, chromium, chromedriver, profile)
        shot_ok = True
        try:
            open_page(driver, page)
            try:
                counts, failures = run_checks(driver, page)
                if args.bed_compare:
                    counts["compared runs"], found = check_bed_compare(driver, page)
                    failures += found
            finally:  # the screenshot is wanted most when something is wrong
                if args.screenshot:
                    shot_ok = save_screenshot(driver, args.screenshot.resolve(), args.full_page)
        finally:
            driver.quit()
    elapsed = time.monotonic() - started

    summary = ", ".join(f"{n} {what}" for what, n in counts.items())
    if failures:
        for failure in failures:
            print(f"FAIL {failure}")
        print(f"report_browser: {len(failures)} failure{'s' if len(failures) != 1 else ''} in {page} ({summary}; {elapsed:.1f} s)")
        return 1
    print(f"report_browser: OK {page}: {summary} checked in {elapsed:.1f} s")
    return 0 if shot_ok else 1


if __name__ == "__main__":
    sys.exit(main())
