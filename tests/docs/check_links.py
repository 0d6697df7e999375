#!/usr/bin/env python3
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Checks that the documentation points only at what exists.

Every Markdown page of the README, CONTRIBUTING and doc/ is read:
- each relative link [text](target) must name a file or folder of the tree
  (relative to the page), and a #fragment must be a heading of the target
  page (GitHub's anchors: lower case, punctuation dropped, spaces to -);
  into doc/benchmarks.md, whose headings carry dates and commits that
  change with every run, only its stable anchors (<a id="solver-bench">)
  may be linked;
- each backquoted path (`modules/session/RunRequest.h`, `tests/cli/`) must
  exist, read from the tree's root or from the page's folder. A module's
  header may be named the short way, modules/M/H.h or M/H.h for
  modules/M/include/tetskin/M/H.h, and tetskin/M/H.h as it is included.

- each path written out in the prose (doc/user/gui.md, modules/session/)
  must exist as well;
and in the sources (modules/, app/, tests/, cmake/, shaders/, the scripts)
each Markdown page a comment names (doc/dev/numerics.md, python.md) must
be a page of the tree.

Prints one line per broken reference (page:line: what) and exits 1 if there
is any. Usage: check_links.py SOURCE_DIR
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
PAGES = [ROOT / "README.md", ROOT / "CONTRIBUTING.md", *sorted((ROOT / "doc").rglob("*.md"))]

LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)\)|!\[[^\]]*\]\(([^)\s]+)\)")
CODE = re.compile(r"`([^`\n]+)`")
# A backquoted path: folders and a file with an extension, or a folder ending
# in '/'; no spaces, no wildcards, no placeholders in capitals (RUN_frames/).
PATH = re.compile(r"^(?:\.{1,2}/)?(?:[\w.+-]+/)+(?:[\w.+-]+\.[A-Za-z0-9]+)?/?$")
# What is written in the tree but not in the repository (builds, outputs),
# and example paths of a user's own.
NOT_IN_TREE = ("build", "out/", "/tmp/", "~/", "/usr", "usr/", "lib/", "etc/", "$")
# A path in prose: one of the tree's top folders, then more.
BARE_PATH = re.compile(r"(?<![\w/`.-])((?:doc|modules|app|tests|data|shaders|cmake|packaging)/[\w./+-]*[\w/])")
# A page named in a source.
PAGE_NAME = re.compile(r"(?<![\w/.-])([\w./-]*[\w-]+\.md)\b")
SOURCES = ["modules", "app", "tests", "cmake", "shaders", "packaging", ".ci"]
SOURCE_FILES = ["tetskin.sh", "CMakeLists.txt"]
# A placeholder in a path (READER, RUN_frames): not a file.
PLACEHOLDER = re.compile(r"(^|/)[A-Z]{3,}(_|/|$)")
HEADINGS = {}


def anchors(page):
    if page not in HEADINGS:
        found, counts = set(), {}
        fenced = False
        for line in page.read_text(encoding="utf-8").splitlines():
            if line.startswith("```"):
                fenced = not fenced
            if fenced or not line.startswith("#"):
                continue
            text = line.lstrip("#").strip()
            slug = re.sub(r"[^\w\- ]", "", text.lower().replace("`", "")).replace(" ", "-")
            n = counts.get(slug, 0)
            counts[slug] = n + 1
            found.add(slug if n == 0 else f"{slug}-{n}")
        for name in re.findall(r'<a (?:name|id)="([^"]+)"', page.read_text(encoding="utf-8")):
            found.add(name)
        HEADINGS[page] = found
    return HEADINGS[page]


def stable_anchors(page):
    return set(re.findall(r'<a id="([^"]+)"></a>', page.read_text(encoding="utf-8")))


def module_header(text):
    """modules/M/H or M/H or tetskin/M/H -> modules/M/include/tetskin/M/H."""
    parts = text.split("/")
    if parts[0] == "modules" and len(parts) == 3:
        parts = parts[1:]
    if parts[0] == "tetskin" and len(parts) == 3:
        parts = parts[1:]
    if len(parts) == 2:
        m, rest = parts
        return [ROOT / "modules" / m / "include" / "tetskin" / m / rest,
                ROOT / "modules" / m / "src" / rest,
                ROOT / "modules" / "filters" / m / rest]
    return []


def path_exists(text, page):
    text = text.rstrip("/")
    candidates = [ROOT / text, page.parent / text, *module_header(text)]
    return any(c.exists() for c in candidates)


def check(page, pages):
    problems = []
    fenced = False
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        for match in LINK.finditer(line):
            target = match.group(1) or match.group(2)
            if re.match(r"^[a-z]+:", target):  # http:, https:, mailto:
                continue
            file, _, fragment = target.partition("#")
            linked = (page.parent / file).resolve() if file else page
            if not linked.exists():
                problems.append(f"{page.relative_to(ROOT)}:{number}: link to {target}: no such file")
            elif fragment and linked.suffix == ".md" and fragment not in anchors(linked):
                problems.append(f"{page.relative_to(ROOT)}:{number}: link to {target}: "
                                f"no heading #{fragment} in {linked.relative_to(ROOT)}")
            elif (fragment and linked == ROOT / "doc" / "benchmarks.md"
                  and fragment not in stable_anchors(linked)):
                problems.append(f"{page.relative_to(ROOT)}:{number}: link to {target}: not one "
                                f"of doc/benchmarks.md's stable anchors (<a id=...>)")
        for match in CODE.finditer(line):
            text = match.group(1)
            if not PATH.match(text) or text.startswith(NOT_IN_TREE) or PLACEHOLDER.search(text):
                continue
            if not path_exists(text, page):
                problems.append(f"{page.relative_to(ROOT)}:{number}: `{text}`: no such file")
        prose = CODE.sub("", LINK.sub("", line))
        for match in BARE_PATH.finditer(prose):
            text = match.group(1).rstrip(".")
            if not PLACEHOLDER.search(text) and not path_exists(text, page):
                problems.append(f"{page.relative_to(ROOT)}:{number}: {text}: no such file")
        for match in PAGE_NAME.finditer(prose):
            name = match.group(1)
            if not (path_exists(name, page) or pathlib.PurePath(name).name in pages):
                problems.append(f"{page.relative_to(ROOT)}:{number}: {name}: no such page")
    return problems


def source_files():
    for top in SOURCES:
        for path in sorted((ROOT / top).rglob("*")):
            if path.is_file() and path.suffix in {".h", ".cpp", ".py", ".cmake", ".txt", ".sh",
                                                  ".glsl", ".in", ""}:
                yield path
    for name in SOURCE_FILES:
        yield ROOT / name


def check_source(path, pages):
    problems = []
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        return problems
    for number, line in enumerate(text.splitlines(), 1):
        for match in PAGE_NAME.finditer(line):
            name = match.group(1).lstrip("/")
            if name.startswith("usr/") or name.startswith("share/"):
                continue  # an installed copy's path
            if not ((ROOT / name).exists() or pathlib.PurePath(name).name in pages):
                problems.append(f"{path.relative_to(ROOT)}:{number}: {name}: no such page")
    return problems


def main():
    pages = {page.name for page in PAGES}
    problems = [p for page in PAGES if page.exists() for p in check(page, pages)]
    problems += [p for path in source_files() for p in check_source(path, pages)]
    for p in problems:
        print(p)
    print(f"{len(PAGES)} pages, {len(problems)} broken reference(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
