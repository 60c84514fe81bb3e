"""The web step in the browser itself: serve build-web/site/, open index.html?bench&... in
headless Chromium (page_check.py's driver), wait for the page to take its benchmark steps (before
it draws anything, src/app/web/main_web.cpp) and print their median step time in ms.

  bench_page.py SITE [--query 'scene=curtain&frames=120'] [--timeout 300]

A benchmark, never a pass or fail: scripts/benchmark-web.sh prints it beside native and node.
"""
import argparse
import functools
import http.server
import os
import shutil
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_check import Chromium, QuietHandler  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('site')
    parser.add_argument('--query', default='scene=curtain&frames=120')
    parser.add_argument('--chromium', default=shutil.which('chromium') or 'chromium')
    parser.add_argument('--timeout', type=float, default=300.0)
    args = parser.parse_args()
    server = http.server.ThreadingHTTPServer(
        ('127.0.0.1', 0), functools.partial(QuietHandler, directory=args.site))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f'http://127.0.0.1:{server.server_address[1]}/index.html?bench&{args.query}'
    profile = tempfile.mkdtemp(prefix='wobble-chromium-')
    browser = Chromium(args.chromium, profile)
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
        shutil.rmtree(profile, ignore_errors=True)


if __name__ == '__main__':
    sys.exit(main())
