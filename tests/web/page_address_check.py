"""A page address with a mistake says so on the page and costs only the mistake: in headless
Chromium, `?scene=flag&k=abc&iterations=20` opens the flag and tells, one line
naming the key, why k was refused; `?scene=flg` opens the default cloth and names the scenes
there are. (Before, both showed the default cloth, the reason only on the console.)

  page_address_check.py SITE [SCREENSHOT_FOLDER]

Exit 0 when every check holds; otherwise one line each that failed.
"""
import base64
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_check import Chromium, serve_site  # noqa: E402
from page_drag_check import Page  # noqa: E402


def main():
    site = sys.argv[1]
    shots = sys.argv[2] if len(sys.argv) > 2 else None
    server, url = serve_site(site)
    failures = []
    cases = [('scene=flag&k=abc&iterations=20', 'flag',
              ['address: k: expected a positive finite number, got \'abc\'']),
             ('scene=flg', 'cloth', ['address: scene: no scene \'flg\' (the scenes: cloth, jelly,']),
             # Each cost the whole address before: the default cloth opened instead.
             ('scene=flag&k=2000&k=50', 'flag', ['address: k: given twice; the last is used']),
             ('scene=banner&self-collision', 'banner',
              ['address: self-collision: not for a course scene']),
             ('scene=course/banner', 'banner', [])]
    for query, scene, told in cases:
        browser = Chromium(shutil.which('chromium') or 'chromium')
        try:
            browser.call('Runtime.enable')
            if not Page(browser, (1280, 720), False).open(f'{url}?{query}'):
                failures.append(f'{query}: the page drew no frames')
                continue
            opened = browser.evaluate('Module.wobbleScene || ""')
            messages = browser.evaluate('Module.wobbleMessages || ""')
            print(f'page_address_check: ?{query}: opened {opened!r}, told {messages!r}')
            if opened != scene:
                failures.append(f'{query}: opened {opened!r}, expected {scene!r}')
            for line in told:
                if line not in messages:
                    failures.append(f'{query}: the page did not say {line!r}')
            if shots:
                data = base64.b64decode(
                    browser.call('Page.captureScreenshot', {'format': 'png'})['data'])
                name = query.replace('&', '_').replace('=', '-')
                with open(os.path.join(shots, f'address_{name}.png'), 'wb') as file:
                    file.write(data)
        finally:
            browser.close()
    server.shutdown()
    for failure in failures:
        print(f'page_address_check: FAILED: {failure}')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
