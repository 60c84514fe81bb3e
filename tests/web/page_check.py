#!/usr/bin/env python3
"""The web page's test: serve build-web/site/ on localhost, open it in headless Chromium (WebGL 2
through SwiftShader), wait until the page has drawn the scene after a fixed number of steps, and
compare a screenshot with a golden image (tests/golden/web_*.png).

Chromium is driven over its DevTools protocol on a pipe (--remote-debugging-pipe), so that the
test can ask the page how many frames it drew (Module.wobbleFrames, Module.wobbleSteps, set by
src/app/web/run_browser.cpp) and time the first one in real seconds.

The address asks for `frames` steps and no more (index.html?frames=N), so the cloth's state in
the picture does not depend on the machine's speed; only the panel's timings do. The images
match when at most --max-share of the pixels differ by more than --tolerance in a channel: a
blank page, a page that could not start, or a scene that is not drawn differs in far more.

  page_check.py SITE GOLDEN [--query ...] [--size 1280x720] [--update] [--expect-mismatch]

Exit 0: the page drew and matched (or, with --expect-mismatch, drew something that does not
match: the test that a broken site fails). On a failure the actual image and a diff are written
beside --out.
"""
import argparse
import base64
import functools
import http.server
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_files import read_png, write_png  # noqa: E402


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map,
                      '.wasm': 'application/wasm', '.js': 'text/javascript'}

    def log_message(self, *args):
        pass


def serve_site(site):
    """Serve the folder `site` on a free port of localhost, on a thread of its own: the server
    (shutdown() ends it) and the page's address without its query."""
    server = http.server.ThreadingHTTPServer(
        ('127.0.0.1', 0), functools.partial(QuietHandler, directory=site))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f'http://127.0.0.1:{server.server_address[1]}/index.html'


class Chromium:
    """Headless Chromium with one page, driven over the DevTools protocol on a pipe, with a
    profile of its own in a temporary folder that close() removes."""

    def __init__(self, executable):
        self.profile = tempfile.mkdtemp(prefix='wobble-chromium-')
        profile = self.profile
        to_chromium_read, to_chromium_write = os.pipe()
        from_chromium_read, from_chromium_write = os.pipe()

        def pipes_on_3_and_4():  # the protocol's descriptors, in the child
            os.dup2(to_chromium_read, 100)
            os.dup2(from_chromium_write, 101)
            os.dup2(100, 3)
            os.dup2(101, 4)

        self.process = subprocess.Popen(
            [executable, '--headless=new', '--no-sandbox', '--use-angle=swiftshader',
             '--enable-unsafe-swiftshader', '--remote-debugging-pipe', '--no-first-run',
             '--hide-scrollbars', '--mute-audio', f'--user-data-dir={profile}', 'about:blank'],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            close_fds=False, preexec_fn=pipes_on_3_and_4)
        os.close(to_chromium_read)
        os.close(from_chromium_write)
        self.writer = os.fdopen(to_chromium_write, 'wb')
        self.reader = os.fdopen(from_chromium_read, 'rb')
        self.next_id = 0
        self.pending = bytearray()  # read from the pipe, not yet a whole message
        self.console = []
        self.events = []  # the protocol's events, as call() read them past its replies
        self.session = None
        targets = self.call('Target.getTargets')['targetInfos']
        page = next(target for target in targets if target['type'] == 'page')
        self.session = self.call('Target.attachToTarget',
                                 {'targetId': page['targetId'], 'flatten': True})['sessionId']

    def _read_message(self):
        # Messages end with a NUL. Read in blocks: a screenshot is megabytes, which a byte at a
        # time took a second of Python each.
        while True:
            end = self.pending.find(b'\0')
            if end >= 0:
                message = self.pending[:end]
                del self.pending[:end + 1]
                return json.loads(message)
            block = self.reader.read1(1 << 20)
            if not block:
                raise RuntimeError('Chromium closed its protocol pipe')
            self.pending += block

    def call(self, method, params=None):
        self.next_id += 1
        message = {'id': self.next_id, 'method': method, 'params': params or {}}
        if self.session:
            message['sessionId'] = self.session
        self.writer.write(json.dumps(message).encode() + b'\0')
        self.writer.flush()
        while True:
            reply = self._read_message()
            if reply.get('method') == 'Runtime.consoleAPICalled':
                self.console.append(' '.join(str(argument.get('value', argument.get('description')))
                                             for argument in reply['params']['args']))
            if reply.get('method') == 'Log.entryAdded':  # the browser's own: WebGL, the network
                entry = reply['params']['entry']
                self.console.append(f'{entry.get("source")}: {entry.get("text")} '
                                    f'{entry.get("url", "")}')
            if 'method' in reply and len(self.events) < 1000:  # for a test that awaits one
                self.events.append(reply)
            if reply.get('id') == self.next_id:
                if 'error' in reply:
                    raise RuntimeError(f'{method}: {reply["error"]}')
                return reply['result']

    def evaluate(self, expression):
        result = self.call('Runtime.evaluate', {'expression': expression, 'returnByValue': True})
        return result['result'].get('value')

    def file_chooser(self, open_it, timeout=10.0):
        """The Page.fileChooserOpened event after open_it() (a key, a click) opened the page's
        file chooser, intercepted so that no dialog shows; None if none opened within timeout
        seconds."""
        self.call('Page.enable')  # its events: the chooser opened
        self.call('Page.setInterceptFileChooserDialog', {'enabled': True})
        self.events.clear()
        open_it()
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            self.evaluate('1')  # reads what arrived
            chooser = next((event for event in self.events
                            if event.get('method') == 'Page.fileChooserOpened'), None)
            if chooser is not None:
                return chooser
            time.sleep(0.2)
        return None

    def close(self):
        try:
            self.call('Browser.close')
        except (RuntimeError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        shutil.rmtree(self.profile, ignore_errors=True)


def compare(actual, golden, tolerance):
    """(share of pixels differing by more than tolerance in a channel, diff rows)."""
    (width, height, rows), (golden_width, golden_height, golden_rows) = actual, golden
    if (width, height) != (golden_width, golden_height):
        return 1.0, None
    differing, diff = 0, []
    for row, golden_row in zip(rows, golden_rows):
        line = bytearray(width * 4)
        for x in range(0, width * 4, 4):
            if (abs(row[x] - golden_row[x]) > tolerance or
                    abs(row[x + 1] - golden_row[x + 1]) > tolerance or
                    abs(row[x + 2] - golden_row[x + 2]) > tolerance):
                differing += 1
                line[x:x + 4] = b'\xff\x00\x00\xff'
            else:
                line[x:x + 4] = bytes((row[x] // 4, row[x + 1] // 4, row[x + 2] // 4, 255))
        diff.append(bytes(line))
    return differing / (width * height), diff


def idle_failure(browser):
    """At rest (the address's steps taken, no input) the page draws a frame about once a second,
    not at the browser's rate (in software, two cores drawing the same picture); a mouse moving
    over it draws at the browser's rate (in SwiftShader about 12 frames a second at 1280x720).
    The failure, or None."""
    frames = 'Module.wobbleFrames'
    before = browser.evaluate(frames)
    time.sleep(3.0)
    at_rest = browser.evaluate(frames) - before
    before = browser.evaluate(frames)
    for step in range(10):
        browser.call('Input.dispatchMouseEvent',
                     {'type': 'mouseMoved', 'x': 1000 + 5 * step, 'y': 400})
        time.sleep(0.1)
    moved = browser.evaluate(frames) - before
    print(f'page_check: at rest {at_rest} frames in 3 s; {moved} in the second the mouse moved')
    if at_rest > 5:
        return f'the page at rest drew {at_rest} frames in 3 s (at most 5: about one a second)'
    if moved < 4:
        return f'the page drew {moved} frames in the second the mouse moved (at least 4)'
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('site')
    parser.add_argument('golden')
    parser.add_argument('--query', default='frames=60', help='the address after "?"')
    parser.add_argument('--size', default='1280x720')
    parser.add_argument('--chromium', default=shutil.which('chromium') or 'chromium')
    parser.add_argument('--first-frame-limit', type=float, default=20.0,
                        help='seconds from opening the address to the first frame drawn')
    parser.add_argument('--timeout', type=float, default=90.0)
    parser.add_argument('--tolerance', type=int, default=24)
    parser.add_argument('--max-share', type=float, default=0.02)
    parser.add_argument('--out', default=None, help='where a failure writes its images')
    parser.add_argument('--update', action='store_true', help='write the golden image')
    parser.add_argument('--expect-mismatch', action='store_true')
    parser.add_argument('--idle-check', action='store_true',
                        help='also check that the page at rest redraws about once a second, and '
                             'at the browser\'s rate again once the mouse moves')
    args = parser.parse_args()
    width, height = (int(value) for value in args.size.split('x'))
    steps = int(dict(pair.split('=') for pair in args.query.split('&') if '=' in pair)
                .get('frames', '0'))

    server, page = serve_site(args.site)
    url = f'{page}?{args.query}'
    browser = Chromium(args.chromium)
    try:
        browser.call('Runtime.enable')
        browser.call('Log.enable')
        browser.call('Emulation.setDeviceMetricsOverride',
                     {'width': width, 'height': height, 'deviceScaleFactor': 1,
                      'mobile': width < 600})
        start = time.monotonic()
        browser.call('Page.navigate', {'url': url})
        first_frame = None
        failure = None
        drawn_after_last_step = None
        while True:
            elapsed = time.monotonic() - start
            state = browser.evaluate(
                '[typeof Module == "object" ? (Module.wobbleFrames || 0) : 0,'
                ' typeof Module == "object" ? (Module.wobbleSteps || 0) : 0,'
                ' (document.getElementById("status") || {}).textContent || ""]') or [0, 0, '']
            frames, shown_steps, status = state
            if frames > 0 and first_frame is None:
                first_frame = elapsed
                print(f'page_check: first frame {first_frame:.2f} s after opening {url}')
            if 'could not start' in status:
                failure = f'the page says: {status}'
                break
            if shown_steps >= steps and frames > 0:
                drawn_after_last_step = drawn_after_last_step or frames
                if frames >= drawn_after_last_step + 3:  # the last step drawn, and settled
                    break
            if elapsed > args.timeout:
                failure = f'{frames} frames, {shown_steps} steps after {args.timeout:.0f} s'
                break
            time.sleep(0.1)
        # A clean console: no WebGL error (glEnable of a desktop-only enum twice a frame) and no
        # file the page asks for missing (the favicon).
        noise = [line for line in browser.console
                 if 'INVALID_ENUM' in line or 'Failed to load resource' in line]
        if noise and not failure:
            failure = f'the console: {noise[0]} ({len(noise)} such lines)'
        if first_frame is not None and first_frame > args.first_frame_limit:
            failure = failure or (f'first frame after {first_frame:.1f} s, more than '
                                  f'{args.first_frame_limit:.0f} s')
        shot = base64.b64decode(browser.call('Page.captureScreenshot', {'format': 'png'})['data'])
        if args.idle_check and not failure:
            failure = idle_failure(browser)
    finally:
        console = browser.console
        browser.close()
        server.shutdown()

    out = args.out or os.path.join(tempfile.gettempdir(), 'wobble-web-' +
                                   os.path.basename(args.golden)[:-4])
    actual_path = out + '_actual.png'
    with open(actual_path, 'wb') as file:
        file.write(shot)
    actual = read_png(actual_path)
    if args.update:
        if failure:
            print(f'page_check: not updating {args.golden}: {failure}', file=sys.stderr)
            return 1
        shutil.copyfile(actual_path, args.golden)
        print(f'page_check: wrote {args.golden}')
        return 0
    share, diff = compare(actual, read_png(args.golden), args.tolerance)
    print(f'page_check: {100 * share:.2f}% of the pixels differ from {args.golden} by more than '
          f'{args.tolerance} (at most {100 * args.max_share:.2f}%)')
    matched = share <= args.max_share and failure is None
    if args.expect_mismatch:
        if matched:
            print('page_check: the page matched the golden image, but should not have',
                  file=sys.stderr)
            return 1
        print(f'page_check: mismatch, as expected ({failure or "the picture differs"})')
        return 0
    if not matched:
        if diff is not None:
            write_png(out + '_diff.png', actual[0], actual[1], diff)
        print(f'page_check: FAILED: {failure or "the picture differs"}; actual {actual_path}'
              f'{", diff " + out + "_diff.png" if diff is not None else ""}', file=sys.stderr)
        for line in console[-20:]:
            print(f'  console: {line}', file=sys.stderr)
        return 1
    os.remove(actual_path)
    return 0


if __name__ == '__main__':
    sys.exit(main())
