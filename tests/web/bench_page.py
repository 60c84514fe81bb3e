"""The web step in the browser itself: serve build-web/site/, open index.html?bench&... in
headless Chromium (page_check.py's driver), wait for the page to take its benchmark steps (before
it draws anything, src/app/web/main_web.cpp) and print their median step time in ms.

  bench_page.py SITE [--query 'scene=curtain&frames=120'] [--timeout 300]

A benchmark, never a pass or fail: scripts/benchmark-web.sh prints it beside native and node.
"""
import argparse
import os
import shutil
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_check import Chromium, serve_site  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('site')
    parser.add_argument('--query', default='scene=curtain&frames=120')
    parser.add_argument('--chromium', default=shutil.which('chromium') or 'chromium')
    parser.add_argument('--timeout', type=float, default=300.0)
    args = parser.parse_args()
    server, page = serve_site(args.site)
    url = f'{page}?bench&{args.query}'
    browser = Chromium(args.chromium)
    try:
        browser.call('Runtime.enable')
        browser.call('Page.navigate', {'url': url})
        start = time.monotonic()
        while True:
            value = browser.evaluate(
                'typeof Module == "object" && Module.wobbleBenchStepMs !== undefined ?'
                ' Module.wobbleBenchStepMs : null')
            if value is not None:
                print(value)
                return 0
            if time.monotonic() - start > args.timeout:
                print(f'bench_page: no result after {args.timeout:.0f} s from {url}',
                      file=sys.stderr)
                return 1
            time.sleep(0.2)
    finally:
        browser.close()
        server.shutdown()


if __name__ == '__main__':
    sys.exit(main())
