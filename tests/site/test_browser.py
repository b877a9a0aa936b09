"""The built site in a real headless browser (Debian's chromium via chromedriver).

Served on 127.0.0.1 from this process; every lesson page must load without a
console error, keep the code of its headings in the TOC, describe every
image, fold its solutions and offer its executed notebook; the palette
toggles and the search finds ``LaunchConfiguration``.  The machine may have
no internet: requests to other hosts (GitHub's repository facts) may fail,
nothing else may.
"""
from __future__ import annotations

import functools
import json
import shutil
import threading
import urllib.request
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from urllib.parse import urljoin, urlparse

import pytest
from selenium import webdriver
from selenium.common.exceptions import TimeoutException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait
from textbook.lessons import load_all
from textbook.render import NO_DESCRIPTION

pytestmark = [pytest.mark.xdist_group('site'), pytest.mark.timeout(1800)]

CHROMIUM = Path('/usr/bin/chromium')
CHROMEDRIVER = Path('/usr/bin/chromedriver')
FLAGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync',
         '--window-size=1600,1200']
WAIT = 30  # seconds, at most, for any state of a page
LESSON_PAGES = [lesson.site_path.removesuffix('.ipynb') + '/' for lesson in load_all()]
#: Pages with a `labkit.exercises.check(...)` cell: each shows at least one verdict.
EXERCISE_PAGES = {lesson.site_path.removesuffix('.ipynb') + '/' for lesson in load_all()
                  if 'exercises.check(' in lesson.text}


class _QuietHandler(SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:  # keep pytest's output to the failures
        pass


@pytest.fixture(scope='module')
def server(site):
    """The site at http://127.0.0.1:<free port>/."""
    httpd = ThreadingHTTPServer(('127.0.0.1', 0),
                                functools.partial(_QuietHandler, directory=str(site)))
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f'http://127.0.0.1:{httpd.server_address[1]}/'
    httpd.shutdown()
    httpd.server_close()
    thread.join(timeout=WAIT)


@pytest.fixture(scope='module')
def browser(tmp_path_factory):
    missing = [str(p) for p in (CHROMIUM, CHROMEDRIVER) if not p.exists()]
    if missing:
        pytest.fail(f"the browser test needs {', '.join(missing)}: install the Debian "
                    f"packages with `apt-get install chromium chromium-driver` (as root, "
                    f"`bash tools/setup_env.sh` does it)", pytrace=False)
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    profile = tmp_path_factory.mktemp('chromium-profile')
    for flag in (*FLAGS, f'--user-data-dir={profile}'):
        options.add_argument(flag)
    options.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
    driver = webdriver.Chrome(service=Service(executable_path=str(CHROMEDRIVER)),
                              options=options)
    driver.set_page_load_timeout(WAIT)
    yield driver
    driver.quit()
    shutil.rmtree(profile, ignore_errors=True)


def open_page(browser, url: str) -> list[str]:
    """Load ``url`` and return its console errors (failed requests to other hosts
    excepted: the test machine may be offline)."""
    browser.get_log('browser')  # drop what earlier pages logged
    browser.get(url)
    WebDriverWait(browser, WAIT).until(
        lambda b: b.execute_script('return document.readyState') == 'complete')
    errors = []
    for entry in browser.get_log('browser'):
        if entry['level'] != 'SEVERE':
            continue
        source = entry['message'].split(' ', 1)[0]
        if 'Failed to load resource' in entry['message'] and \
                urlparse(source).hostname not in (None, '127.0.0.1'):
            continue
        errors.append(entry['message'])
    return errors


@pytest.mark.parametrize('page', LESSON_PAGES)
def test_lesson_page_in_the_browser(browser, server, page):
    errors = open_page(browser, server + page)
    assert errors == [], f'{page}: console errors:\n' + '\n'.join(errors)

    headings = browser.find_elements(By.CSS_SELECTOR, 'article h2[id], article h3[id]')
    toc = {link.get_attribute('href').split('#', 1)[1]: link.get_attribute('textContent')
           for link in browser.find_elements(By.CSS_SELECTOR,
                                             'nav.md-nav--secondary a.md-nav__link')}
    with_code = [h for h in headings if h.find_elements(By.TAG_NAME, 'code')]
    for heading in with_code:
        code = ' '.join(c.get_attribute('textContent')
                        for c in heading.find_elements(By.TAG_NAME, 'code'))
        entry = toc.get(heading.get_attribute('id'))
        assert entry is not None, f"{page}: heading #{heading.get_attribute('id')} not in the TOC"
        assert code.split()[0] in entry, f'{page}: TOC entry {entry.strip()!r} lost {code!r}'

    for image in browser.find_elements(By.CSS_SELECTOR, 'article img'):
        alt = (image.get_attribute('alt') or '').strip()
        assert alt and alt != NO_DESCRIPTION, f'{page}: an image has no description'
        assert browser.execute_script('return arguments[0].naturalWidth', image) > 0

    for fold in browser.find_elements(By.CSS_SELECTOR, 'details.textbook-solution'):
        assert fold.get_attribute('open') is None, f'{page}: a solution is unfolded'
        inside = fold.find_elements(By.CSS_SELECTOR, ':scope > .jp-Cell')
        assert inside and not any(cell.is_displayed() for cell in inside)

    article = browser.find_element(By.CSS_SELECTOR, 'article').get_attribute('textContent')
    assert 'Verdict(' not in article, f'{page}: a verdict shows as a Python repr'
    verdicts = browser.find_elements(By.CSS_SELECTOR, 'article .labkit-verdict')
    assert verdicts or page not in EXERCISE_PAGES, f'{page}: no exercise verdict shown'
    for verdict in verdicts:
        items = [item.get_attribute('textContent')
                 for item in verdict.find_elements(By.CSS_SELECTOR, 'ul > li')]
        assert items and all(item[:2] in ('✓ ', '✗ ') for item in items), (page, items)

    assert browser.find_elements(By.CSS_SELECTOR, '.textbook-header a, .textbook-header')
    assert browser.find_elements(By.CSS_SELECTOR, '.textbook-key-points h2#key-points')
    edit = browser.find_element(By.CSS_SELECTOR, "a.md-content__button[title='Edit this page']")
    assert edit.get_attribute('href').endswith(
        f"/lessons/{page.rstrip('/')}.md"), edit.get_attribute('href')

    download = browser.find_element(By.CSS_SELECTOR,
                                    "a[title='Download the executed notebook']")
    with urllib.request.urlopen(urljoin(browser.current_url, download.get_attribute('href')),
                                timeout=WAIT) as response:
        notebook = json.load(response)
    assert notebook['nbformat'] == 4 and any(
        cell.get('outputs') for cell in notebook['cells'] if cell['cell_type'] == 'code')


def test_graphs_share_one_scale(browser, server):
    """6.3 shows two graphs of different widths: both at the same pixels per inch."""
    page = next(p for p in LESSON_PAGES if '/03_' in p)
    open_page(browser, server + page)
    images = browser.find_elements(By.CSS_SELECTOR, 'figure.ros-graph img')
    assert len(images) >= 2
    scales = [browser.execute_script(
        'return arguments[0].clientWidth / arguments[0].naturalWidth', image) for image in images]
    assert max(scales) - min(scales) < 0.01, scales
    captions = browser.find_elements(By.CSS_SELECTOR, 'figure.ros-graph figcaption')
    assert len(captions) == len(images) and all(c.text.strip() for c in captions)


def test_palette_toggles_between_light_and_dark(browser, server):
    open_page(browser, server)
    scheme = "return document.body.getAttribute('data-md-color-scheme')"
    before = browser.execute_script(scheme)
    toggle = next(label for label in browser.find_elements(
        By.CSS_SELECTOR, "form[data-md-component='palette'] label") if label.is_displayed())
    toggle.click()
    WebDriverWait(browser, WAIT).until(lambda b: b.execute_script(scheme) != before)
    assert {before, browser.execute_script(scheme)} == {'default', 'slate'}


def test_search_finds_launch_configuration(browser, server):
    open_page(browser, server)
    field = browser.find_element(By.CSS_SELECTOR, 'input.md-search__input')
    if not field.is_displayed():  # narrow window: the search opens from a header button
        browser.find_element(By.CSS_SELECTOR, "label.md-header__button[for='__search']").click()
        WebDriverWait(browser, WAIT).until(lambda b: field.is_displayed())
    field.click()
    field.send_keys('LaunchConfiguration')
    try:
        WebDriverWait(browser, WAIT).until(lambda b: b.find_elements(
            By.CSS_SELECTOR, 'li.md-search-result__item'))
    except TimeoutException:
        pytest.fail('the site search found nothing for LaunchConfiguration')
    results = browser.find_element(By.CSS_SELECTOR, '.md-search-result').text
    assert 'LaunchConfiguration' in results


def test_files_side_by_side_are_tabs_that_switch(browser, server):
    """6.11's Python/XML/YAML groups are tabs: one file shows, a label switches it."""
    page = next(p for p in LESSON_PAGES if '/11_' in p)
    open_page(browser, server + page)
    tab_set = browser.find_element(By.CSS_SELECTOR, 'div.tabbed-set')
    labels = tab_set.find_elements(By.CSS_SELECTOR, '.tabbed-labels > label')
    blocks = tab_set.find_elements(By.CSS_SELECTOR, '.tabbed-content > .tabbed-block')
    assert [label.text for label in labels] == ['Python', 'XML', 'YAML']
    assert [block.is_displayed() for block in blocks] == [True, False, False]
    labels[1].click()
    WebDriverWait(browser, WAIT).until(lambda b: blocks[1].is_displayed())
    assert [block.is_displayed() for block in blocks] == [False, True, False]
    assert 'bringup_formats.launch.xml' in blocks[1].text
