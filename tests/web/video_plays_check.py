#!/usr/bin/env python3
"""A recording plays in a browser: wobble records the flag headless as FILE.webm and FILE.mp4
(--record), a local server serves them, and headless Chromium opens each in a <video> element.
For each: the metadata arrive with the recorded size and the simulated duration (frames x dt),
play() starts, currentTime advances while it plays, and the picture drawn from the video onto a
canvas is the flag (not one flat colour).

  video_plays_check.py WOBBLE SCENE [--frames 120] [--size 320x180] [--dt 0.016667]

Exit 0 when every check holds for every format; otherwise one line each that failed. A format
this Chromium cannot play at all (canPlayType says "") fails too: the docs say which to use.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_check import Chromium, serve_site  # noqa: E402

PAGE = '<!doctype html><html><body style="margin:0;background:#000"></body></html>\n'

# Opens NAME in a <video>, waits for its metadata, plays it for about a second and reports.
PLAY = '''(async (name, type) => {
  const video = document.createElement('video');
  video.muted = true;
  video.playsInline = true;
  document.body.appendChild(video);
  const report = {can_play: video.canPlayType(type)};
  const failed = () => (video.error ? `error ${video.error.code}: ${video.error.message}` : '');
  try {
    await new Promise((resolve, reject) => {
      video.onloadedmetadata = resolve;
      video.onerror = () => reject(failed());
      setTimeout(() => reject('no loadedmetadata in 20 s'), 20000);
      video.src = name;
    });
    Object.assign(report, {width: video.videoWidth, height: video.videoHeight,
                           duration: video.duration});
    await video.play();
    const wall = performance.now(), start = video.currentTime;
    await new Promise(resolve => setTimeout(resolve, 800));
    report.advanced = video.currentTime - start;
    report.wall = (performance.now() - wall) / 1000;
    report.playing = !video.paused;
    const canvas = document.createElement('canvas');
    canvas.width = video.videoWidth;
    canvas.height = video.videoHeight;
    const context = canvas.getContext('2d');
    context.drawImage(video, 0, 0);
    const pixels = context.getImageData(0, 0, canvas.width, canvas.height).data;
    let sum = 0, squares = 0, count = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      const grey = (pixels[i] + pixels[i + 1] + pixels[i + 2]) / 3;
      sum += grey; squares += grey * grey; ++count;
    }
    report.grey_spread = Math.sqrt(Math.max(0, squares / count - (sum / count) ** 2));
  } catch (error) {
    report.error = String(error) || failed();
  }
  return JSON.stringify(report);
})'''

TYPES = {'.webm': 'video/webm; codecs="vp9"', '.mp4': 'video/mp4; codecs="avc1.64001f"'}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('wobble')
    parser.add_argument('scene')
    parser.add_argument('--frames', type=int, default=120)
    parser.add_argument('--size', default='320x180')
    parser.add_argument('--dt', type=float, default=0.016667, help="the scene's dt (s)")
    parser.add_argument('--chromium', default=shutil.which('chromium') or 'chromium')
    args = parser.parse_args()
    width, height = (int(value) for value in args.size.split('x'))
    folder = tempfile.mkdtemp(prefix='wobble-video-')
    failures = []
    try:
        with open(os.path.join(folder, 'index.html'), 'w') as page:
            page.write(PAGE)
        for extension in TYPES:
            video = os.path.join(folder, 'recording' + extension)
            run = subprocess.run([args.wobble, args.scene, '--headless', '--frames',
                                  str(args.frames), '--width', str(width), '--height', str(height),
                                  '--record', video], capture_output=True, text=True, timeout=120)
            if run.returncode != 0:
                failures.append(f'{extension}: wobble --record exited {run.returncode}: '
                                f'{run.stderr.strip()}')
        server, url = serve_site(folder)
        browser = Chromium(args.chromium)
        try:
            browser.call('Runtime.enable')
            browser.call('Page.navigate', {'url': url})
            for _ in range(100):
                if browser.evaluate('document.readyState') == 'complete':
                    break
                time.sleep(0.1)
            for extension, type_ in TYPES.items():
                if not os.path.exists(os.path.join(folder, 'recording' + extension)):
                    continue
                reply = browser.call('Runtime.evaluate', {
                    'expression': f'{PLAY}({json.dumps("recording" + extension)}, '
                                  f'{json.dumps(type_)})',
                    'awaitPromise': True, 'returnByValue': True})
                report = json.loads(reply['result']['value'])
                size = os.path.getsize(os.path.join(folder, 'recording' + extension))
                print(f'video_plays_check: {extension} ({size} bytes): {report}')
                expected = args.frames * args.dt
                if not report.get('can_play'):
                    failures.append(f'{extension}: this Chromium says it cannot play {type_}')
                if 'error' in report:
                    failures.append(f'{extension}: {report["error"]}')
                    continue
                if (report['width'], report['height']) != (width, height):
                    failures.append(f'{extension}: {report["width"]}x{report["height"]}, '
                                    f'expected {width}x{height}')
                if abs(report['duration'] - expected) > 0.02:
                    failures.append(f'{extension}: duration {report["duration"]:.3f} s, expected '
                                    f'{expected:.3f} s ({args.frames} frames of {args.dt} s)')
                # Played at about its own speed: a stalled or a racing clock fails.
                if not 0.4 * report['wall'] < report['advanced'] < 1.6 * report['wall'] + 0.1:
                    failures.append(f'{extension}: currentTime advanced {report["advanced"]:.2f} '
                                    f's in {report["wall"]:.2f} s of playing')
                if report['grey_spread'] < 10:
                    failures.append(f'{extension}: the picture is flat (spread '
                                    f'{report["grey_spread"]:.1f}): no flag decoded')
        finally:
            browser.close()
            server.shutdown()
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    for failure in failures:
        print(f'video_plays_check: FAILED {failure}')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
