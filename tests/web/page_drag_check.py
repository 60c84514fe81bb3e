"""The page answers the mouse, a finger and the keys as the desktop does: in headless Chromium
(page_check.py's driver, DevTools input events), the cloth's pinned corner is taken with the
mouse and dragged, then with a finger on a phone-sized page, W turns the course's wind on, and
the wheel zooms a notch at a time, the desktop's way (wheel_checks). The very first wheel, over
the panel before the mouse has moved, scrolls the panel and leaves the camera alone (the page
gives the wheel's own place to the panel first).

The held vertex is drawn as a yellow dot (the desktop's mark): after each drag the yellow dot
must be where the pointer let go, not where the corner was; before it, none there. W must tick
the panel's "wind (W)" box (its pixels change from the unticked box's).

  page_drag_check.py SITE

Exit 0 when every check holds; otherwise one line each that failed.
"""
import base64
import os
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_check import Chromium, serve_site  # noqa: E402
from png_files import read_png  # noqa: E402


def yellow_near(image, x, y, radius=10):
    """Pixels of the held vertex's yellow mark within `radius` of (x, y)."""
    width, height, pixels = image
    count = 0
    for j in range(max(0, y - radius), min(height, y + radius + 1)):
        for i in range(max(0, x - radius), min(width, x + radius + 1)):
            r, g, b = pixels[j][4 * i:4 * i + 3]
            count += r > 200 and g > 170 and b < 90
    return count


def pixel(image, x, y):
    """The RGB of one pixel, as a tuple."""
    return tuple(image[2][y][4 * x:4 * x + 3])


class Page:
    def __init__(self, browser, size, mobile, ratio=1):
        self.browser = browser
        self.browser.call('Emulation.setDeviceMetricsOverride',
                          {'width': size[0], 'height': size[1], 'deviceScaleFactor': ratio,
                           'mobile': mobile})

    def open(self, url, timeout=60.0):
        self.browser.call('Page.navigate', {'url': url})
        start = time.monotonic()
        while time.monotonic() - start < timeout:
            frames = self.browser.evaluate(
                'typeof Module == "object" ? (Module.wobbleFrames || 0) : 0') or 0
            if frames > 10:
                return True
            time.sleep(0.2)
        return False

    def screenshot(self):
        data = base64.b64decode(
            self.browser.call('Page.captureScreenshot', {'format': 'png'})['data'])
        with tempfile.NamedTemporaryFile(suffix='.png', delete=False) as file:
            file.write(data)
        try:
            return read_png(file.name)
        finally:
            os.unlink(file.name)

    def mouse(self, kind, x, y, buttons=0):
        event = {'type': kind, 'x': x, 'y': y}
        if kind != 'mouseMoved' or buttons:
            event.update({'button': 'left', 'buttons': buttons, 'clickCount': 1})
        self.browser.call('Input.dispatchMouseEvent', event)

    def touch(self, kind, points):
        self.browser.call('Input.dispatchTouchEvent',
                          {'type': kind, 'touchPoints': [{'x': x, 'y': y} for x, y in points]})


def drag(page, start, end, finger):
    """Press at `start`, move to `end` in steps with pauses, and hold there; the screenshot."""
    steps = 12
    if finger:
        page.touch('touchStart', [start])
    else:
        page.mouse('mouseMoved', *start)
        time.sleep(0.2)
        page.mouse('mousePressed', *start, buttons=1)
    for step in range(1, steps + 1):
        time.sleep(0.08)
        point = (start[0] + (end[0] - start[0]) * step // steps,
                 start[1] + (end[1] - start[1]) * step // steps)
        if finger:
            page.touch('touchMove', [point])
        else:
            page.mouse('mouseMoved', *point, buttons=1)
    time.sleep(1.0)
    shot = page.screenshot()
    if finger:
        page.touch('touchEnd', [])
    else:
        page.mouse('mouseReleased', *end, buttons=0)
    return shot


def wheel_checks(page):
    """A mouse's notch up zooms in by one notch (the camera 1.15 times nearer), a trackpad's
    small delta by a share of one, and the wheel over the panel leaves the camera alone."""
    failures = []

    def distance():
        return page.browser.evaluate('Module.wobbleCameraDistance || 0') or 0

    def wheel(x, y, delta_y):
        page.browser.call('Input.dispatchMouseEvent',
                          {'type': 'mouseWheel', 'x': x, 'y': y, 'deltaX': 0, 'deltaY': delta_y})
        time.sleep(0.6)

    page.mouse('mouseMoved', 1000, 400)
    time.sleep(0.3)
    for delta_y, low, high, what in [(-100, 1 / 1.17, 1 / 1.13, 'a notch up: one notch nearer'),
                                     (100, 1.13, 1.17, 'a notch down: one notch back'),
                                     (4, 1.0, 1.02, 'a trackpad\'s small delta: a little')]:
        before = distance()
        wheel(1000, 400, delta_y)
        after = distance()
        ratio = after / before if before else 0
        print(f'page_drag_check: wheel {delta_y}: the camera {before:.4f} -> {after:.4f} m '
              f'({ratio:.4f}x)')
        if not low <= ratio <= high:
            failures.append(f'wheel {delta_y}: distance x{ratio:.4f}, expected {what}')
    page.mouse('mouseMoved', 150, 300)
    time.sleep(0.3)
    before = distance()
    wheel(150, 300, -100)
    if distance() != before:
        failures.append('the wheel over the panel moved the camera')
    return failures


def main():
    site = sys.argv[1]
    server, url = serve_site(site)
    failures = []
    # (size, mobile, the pinned corner's pixel as the cloth opens, where the drag ends)
    cases = [((1280, 720), False, (767, 155), (647, 305)),
             ((390, 844), True, (168, 297), (93, 417))]
    for size, finger, corner, end in cases:
        what = f'{size[0]}x{size[1]} {"finger" if finger else "mouse"}'
        browser = Chromium(shutil.which('chromium') or 'chromium')
        try:
            browser.call('Runtime.enable')
            page = Page(browser, size, finger)
            if not page.open(url):
                failures.append(f'{what}: the page drew no frames')
                continue
            if not finger:
                # The first event the page gets: a wheel over the panel, the mouse never moved.
                distance = page.browser.evaluate('Module.wobbleCameraDistance')
                page.browser.call('Input.dispatchMouseEvent',
                                  {'type': 'mouseWheel', 'x': 150, 'y': 300, 'deltaX': 0,
                                   'deltaY': -100})
                time.sleep(0.6)
                after = page.browser.evaluate('Module.wobbleCameraDistance')
                print(f'page_drag_check: the first wheel, over the panel: the camera '
                      f'{distance:.4f} -> {after:.4f} m')
                if after != distance:
                    failures.append('the first wheel over the panel zoomed the camera')
            before = page.screenshot()
            if yellow_near(before, *end) > 0:
                failures.append(f'{what}: a yellow mark where the drag ends before it started')
            during = drag(page, corner, end, finger)
            held = yellow_near(during, *end)
            print(f'page_drag_check: {what}: {held} yellow pixels at the pointer '
                  f'({yellow_near(during, *corner)} where the corner was)')
            if held < 20:
                failures.append(f'{what}: the corner was not held at the pointer ({held} px)')
            if not finger:
                box = (27, 368)  # the "wind (W)" box, in the panel as it opens at 1280x720
                unticked = pixel(before, *box)
                page.browser.call('Input.dispatchKeyEvent',
                                  {'type': 'keyDown', 'key': 'w', 'code': 'KeyW',
                                   'windowsVirtualKeyCode': 87, 'text': 'w'})
                time.sleep(0.15)
                page.browser.call('Input.dispatchKeyEvent',
                                  {'type': 'keyUp', 'key': 'w', 'code': 'KeyW',
                                   'windowsVirtualKeyCode': 87})
                time.sleep(1.0)
                ticked = pixel(page.screenshot(), *box)
                print(f'page_drag_check: the wind box {unticked} before W, {ticked} after')
                if sum(abs(a - b) for a, b in zip(unticked, ticked)) < 60:
                    failures.append('W did not tick the wind box')
                failures += wheel_checks(page)
        finally:
            browser.close()
    server.shutdown()
    for failure in failures:
        print(f'page_drag_check: FAILED: {failure}')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
