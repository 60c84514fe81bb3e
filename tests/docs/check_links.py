#!/usr/bin/env python3
"""Check the links and images of README.md and docs/*.md, and the README's length.

Usage: python3 tests/docs/check_links.py ROOT

Every relative link or image target must name a file or folder that exists, relative to the
page it is on. Where it has a #fragment and names a Markdown page (or is only a fragment), a
heading of that page must give that anchor as GitHub makes it: lowercase, markup and
punctuation other than '-' and '_' removed, each space a '-', and '-1', '-2', ... after a
repeated heading. http(s) and mailto links are not checked, nor anything in code (fenced blocks
and `inline code`).

Prints `FILE:LINE: broken link TARGET` for each broken one, and one line if README.md is longer
than README_MAX_LINES; exits with 1 if anything was printed, 0 otherwise.
"""
import os
import re
import sys
import unicodedata

README_MAX_LINES = 250

FENCE = re.compile(r"^\s{0,3}(`{3,}|~{3,})")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
INLINE_CODE = re.compile(r"(`+)(.+?)\1")
# [text](target "title") and ![alt](target), text with at most one level of nested brackets.
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?([^)\s>]*)>?(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")
# [label]: target, a reference definition.
REFERENCE = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
EXTERNAL = re.compile(r"^(?:[a-zA-Z][a-zA-Z0-9+.-]*:|//)")  # http:, https:, mailto:, ...
LINE_ANCHOR = re.compile(r"^L\d+(?:-L\d+)?$")  # GitHub's line anchors in a source file


def outside_fences(text):
    """Yield (line number, line) for the lines outside fenced code blocks."""
    fence = None
    for number, line in enumerate(text.splitlines(), start=1):
        match = FENCE.match(line)
        if fence is None and match:
            fence = match.group(1)
            continue
        if fence is not None:
            if match and match.group(1)[0] == fence[0] and len(match.group(1)) >= len(fence):
                fence = None
            continue
        yield number, line


def prose_lines(text):
    """Yield (line number, line) outside fenced code blocks, with inline code blanked."""
    for number, line in outside_fences(text):
        yield number, INLINE_CODE.sub(lambda m: " " * len(m.group(0)), line)


def anchor(heading):
    """The anchor GitHub gives a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link keeps its text
    text = re.sub(r"<[^>]+>", "", text)  # HTML tags
    text = text.lower()
    kept = []
    for character in text:
        category = unicodedata.category(character)
        if character in "-_" or character == " " or category[0] in "LN" or category == "Mn":
            kept.append(character)
    return "".join(kept).replace(" ", "-")


anchor_cache = {}


def anchors_of(path):
    if path not in anchor_cache:
        with open(path, encoding="utf-8") as file:
            text = file.read()
        found = set()
        counts = {}
        for _, line in outside_fences(text):
            heading = HEADING.match(line)
            if heading:
                base = anchor(heading.group(2))
                count = counts.get(base, 0)
                counts[base] = count + 1
                found.add(base if count == 0 else f"{base}-{count}")
        anchor_cache[path] = found
    return anchor_cache[path]


def broken(page, target):
    """Why `target`, linked from `page`, does not resolve, or None when it does."""
    path, _, fragment = target.partition("#")
    resolved = page if path == "" else os.path.normpath(os.path.join(os.path.dirname(page), path))
    if not os.path.exists(resolved):
        return "no such file"
    if not fragment:
        return None
    if resolved.endswith(".md"):
        return None if fragment in anchors_of(resolved) else "no such heading"
    return None if LINE_ANCHOR.match(fragment) else "no such heading"


def main():
    if len(sys.argv) != 2:
        print("usage: check_links.py ROOT", file=sys.stderr)
        return 2
    root = sys.argv[1]
    readme = os.path.join(root, "README.md")
    docs = os.path.join(root, "docs")
    pages = [readme] + sorted(
        os.path.join(docs, name) for name in os.listdir(docs) if name.endswith(".md"))
    problems = 0
    for page in pages:
        shown = os.path.relpath(page, root)
        with open(page, encoding="utf-8") as file:
            text = file.read()
        for number, line in prose_lines(text):
            targets = [m.group(1) for m in LINK.finditer(line)]
            reference = REFERENCE.match(line)
            if reference:
                targets.append(reference.group(1))
            for target in targets:
                if target == "" or EXTERNAL.match(target):
                    continue
                if broken(page, target):
                    print(f"{shown}:{number}: broken link {target}")
                    problems += 1
    with open(readme, encoding="utf-8") as file:
        lines = len(file.read().splitlines())
    if lines > README_MAX_LINES:
        print(f"README.md: {lines} lines, more than {README_MAX_LINES}: "
              "move the detail into a page under docs/")
        problems += 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
