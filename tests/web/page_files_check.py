"""The page gives its files to the browser: in headless Chromium at 1280x720, the panel's PNG
button downloads a PNG of what the canvas shows, OBJ the cloth's 1600 vertices, and Save scene
the scene and its mesh, each under the desktop's name (wobble-cloth-0001.png, ...). (Before,
they were written into the page's memory, where nobody could reach them.) After Save scene the
notice on screen says what is true in a page (the download, and a drop to open it again), not
the desktop's `wobble FILE` and scene picker. Ctrl+S saves the scene too, and the page keeps the
key from the browser (its keydown's default prevented: no "Save page" dialog); so does Cmd+S, a
Mac's Ctrl+S, without taking a step as S does; Ctrl+O opens the browser's file chooser.

  page_files_check.py SITE

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


def click(browser, x, y):
    for kind in ('mouseMoved', 'mousePressed', 'mouseReleased'):
        event = {'type': kind, 'x': x, 'y': y}
        if kind != 'mouseMoved':
            event.update({'button': 'left', 'buttons': 1 if kind == 'mousePressed' else 0,
                          'clickCount': 1})
        browser.call('Input.dispatchMouseEvent', event)
        time.sleep(0.15)


def wait_for(path, timeout=20.0):
    start = time.monotonic()
    while time.monotonic() - start < timeout:
        if os.path.exists(path) and os.path.getsize(path) > 0:
            time.sleep(0.3)  # the browser finishes writing
            return True
        time.sleep(0.2)
    return False


def press_with(browser, modifier, key):
    """`key` (a letter) pressed with `modifier` (Control or Meta) held, as DevTools types it."""
    held = {'Control': ('ControlLeft', 17, 2), 'Meta': ('MetaLeft', 91, 4)}
    code, number, bit = held[modifier]
    letter = (key, f'Key{key.upper()}', ord(key.upper()))
    for kind, (name, key_code, key_number) in [('rawKeyDown', (modifier, code, number)),
                                               ('rawKeyDown', letter), ('keyUp', letter),
                                               ('keyUp', (modifier, code, number))]:
        browser.call('Input.dispatchKeyEvent',
                     {'type': kind, 'key': name, 'code': key_code, 'modifiers': bit,
                      'windowsVirtualKeyCode': key_number})
        time.sleep(0.15)


def main():
    site = sys.argv[1]
    server, url = serve_site(site)
    folder = tempfile.mkdtemp(prefix='wobble-downloads-')
    failures = []
    browser = Chromium(shutil.which('chromium') or 'chromium')
    try:
        browser.call('Runtime.enable')
        # A browser-wide setting: sent outside the page's session.
        session, browser.session = browser.session, None
        browser.call('Browser.setDownloadBehavior', {'behavior': 'allow', 'downloadPath': folder})
        browser.session = session
        browser.call('Emulation.setDeviceMetricsOverride',
                     {'width': 1280, 'height': 720, 'deviceScaleFactor': 1, 'mobile': False})
        browser.call('Page.navigate', {'url': f'{url}?frames=30'})
        start = time.monotonic()
        while time.monotonic() - start < 60:
            steps = browser.evaluate('typeof Module == "object" ? (Module.wobbleSteps || 0) : 0')
            if steps and steps >= 30:
                break
            time.sleep(0.2)
        time.sleep(0.5)
        # The save row as the panel opens at 1280x720: Save scene, OBJ, PNG.
        buttons = {'save scene': (57, 92), 'obj': (118, 92), 'png': (155, 92)}
        click(browser, *buttons['png'])
        time.sleep(1.0)
        print('page_files_check: the page offered', browser.evaluate('Module.wobbleDownloads || []'))
        png = os.path.join(folder, 'wobble-cloth-0001.png')
        if not wait_for(png):
            failures.append(f'PNG: no download ({os.listdir(folder)})')
        else:
            width, height, pixels = read_png(png)
            shot_path = os.path.join(folder, 'screenshot.png')
            with open(shot_path, 'wb') as file:
                file.write(base64.b64decode(
                    browser.call('Page.captureScreenshot', {'format': 'png'})['data']))
            _, _, shot = read_png(shot_path)
            # Where the cloth is, the download and the screen agree (the panel's timings may not).
            differing = sum(1 for y in range(100, 600, 10) for x in range(400, 1200, 10)
                            if max(abs(a - b) for a, b in zip(pixels[y][4 * x:4 * x + 3],
                                                              shot[y][4 * x:4 * x + 3])) > 40)
            print(f'page_files_check: PNG {width}x{height}, {differing} of 4000 sampled pixels '
                  f'differ from the screen')
            if (width, height) != (1280, 720):
                failures.append(f'PNG: {width}x{height}, expected the canvas, 1280x720')
            if differing > 200:
                failures.append(f'PNG: {differing} of 4000 pixels differ from what the page shows')
        click(browser, *buttons['obj'])
        obj = os.path.join(folder, 'wobble-cloth-0001.obj')
        if not wait_for(obj):
            failures.append(f'OBJ: no download ({os.listdir(folder)})')
        else:
            with open(obj) as file:
                vertices = sum(1 for line in file if line.startswith('v '))
            print(f'page_files_check: OBJ with {vertices} vertices')
            if vertices != 1600:
                failures.append(f'OBJ: {vertices} vertices, expected 1600')
        click(browser, *buttons['save scene'])
        scene = os.path.join(folder, 'wobble-cloth-scene-0001.json')
        if not wait_for(scene) or not wait_for(os.path.join(folder,
                                                            'wobble-cloth-scene-0001.obj')):
            failures.append(f'Save scene: no scene and mesh ({os.listdir(folder)})')
        else:
            print('page_files_check: the scene and its mesh downloaded')
        notices = browser.evaluate('Module.wobbleNotices || ""')
        print(f'page_files_check: after Save scene the page says: {notices!r}')
        if ('downloaded wobble-cloth-scene-0001.json' not in notices or 'drop' not in notices
                or 'wobble ./' in notices or 'picker' in notices):
            failures.append(f'Save scene: the notice is not the page\'s: {notices!r}')
        # Ctrl+S: a second scene downloads, and the browser's own Ctrl+S was prevented (read by a
        # listener added after the page's, on the same phase: it sees the page's decision).
        browser.evaluate('''window.wobbleKeyPrevented = null; window.addEventListener('keydown',
            (e) => { if (e.key === 's') window.wobbleKeyPrevented = e.defaultPrevented; }, true)''')
        press_with(browser, 'Control', 's')
        second = os.path.join(folder, 'wobble-cloth-scene-0002.json')
        prevented = browser.evaluate('window.wobbleKeyPrevented')
        saved = wait_for(second)
        print(f'page_files_check: Ctrl+S: downloaded {saved}, the browser\'s default prevented '
              f'{prevented}')
        if not saved:
            failures.append(f'Ctrl+S: no scene downloaded ({os.listdir(folder)})')
        if prevented is not True:
            failures.append(f'Ctrl+S: the browser\'s own Ctrl+S was not prevented ({prevented})')
        # Cmd+S, a Mac's Ctrl+S, saves a third scene, and is not S, a step (the page stopped at
        # its 30 steps).
        steps = browser.evaluate('Module.wobbleSteps')
        press_with(browser, 'Meta', 's')
        third = os.path.join(folder, 'wobble-cloth-scene-0003.json')
        saved = wait_for(third)
        time.sleep(0.5)
        stepped = browser.evaluate('Module.wobbleSteps') - steps
        print(f'page_files_check: Cmd+S: downloaded {saved}, {stepped} steps taken')
        if not saved:
            failures.append(f'Cmd+S: no scene downloaded ({os.listdir(folder)})')
        if stepped:
            failures.append(f'Cmd+S: the page took {stepped} steps, as S does')
        # Ctrl+O opens the browser's file chooser, as "Open file..." does, and the view stays
        # (O alone is the scene's opening view).
        chooser = browser.file_chooser(lambda: press_with(browser, 'Control', 'o'))
        print(f'page_files_check: Ctrl+O: a file chooser opened: {chooser is not None}')
        if chooser is None:
            failures.append('Ctrl+O: no file chooser opened')
    finally:
        browser.close()
        server.shutdown()
        shutil.rmtree(folder, ignore_errors=True)
    for failure in failures:
        print(f'page_files_check: FAILED: {failure}')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
