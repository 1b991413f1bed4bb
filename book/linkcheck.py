#!/usr/bin/env python3
"""Link check of the built book (stdlib only).

Usage: python3 book/linkcheck.py [BOOK_HTML_DIR]   (default: book/book, beside this file)

Checks every HTML page under the directory:
- every relative href/src/srcset/data (links, stylesheets, scripts, images,
  frames) resolves to a file of the built book, and a #fragment to an id (or
  <a name>) in the target page;
- no page *loads* anything from the network: an absolute http(s) or
  protocol-relative URL in <script src>, <link href> (stylesheets, icons,
  preloads), <img>/<source>/<iframe>/<embed>/<video>/<audio> src, <object
  data>, an inline style's url(...), or, in any stylesheet the book links,
  url(...) and @import (fonts, images). A link the reader may click (<a
  href="https://…">) is fine.
Relative url(...) in linked stylesheets must resolve too.

Exit status 0 when all is well, 1 with one line per problem otherwise.
"""

import html.parser
import os
import re
import sys
import urllib.parse

# Attributes that name a resource the browser fetches when the page loads.
LOADED = {
    "script": ["src"],
    "link": ["href"],
    "img": ["src", "srcset"],
    "source": ["src", "srcset"],
    "iframe": ["src"],
    "frame": ["src"],
    "embed": ["src"],
    "video": ["src", "poster"],
    "audio": ["src"],
    "track": ["src"],
    "input": ["src"],
    "object": ["data"],
}
# Attributes that name a page the reader may go to (must resolve when relative).
FOLLOWED = {"a": ["href"], "area": ["href"]}
# <link rel=…> values that only name a page (the browser fetches nothing).
NOT_LOADED_RELS = {"canonical", "alternate", "next", "prev", "author", "license", "help", "search"}

CSS_URL = re.compile(r"""url\(\s*(['"]?)(.*?)\1\s*\)""")
CSS_IMPORT = re.compile(r"""@import\s+(['"])(.*?)\1""")
CSS_COMMENT = re.compile(r"/\*.*?\*/", re.S)


def is_remote(url):
    scheme = urllib.parse.urlsplit(url).scheme.lower()
    return scheme in ("http", "https", "ftp", "ws", "wss") or url.startswith("//")


def is_skipped(url):
    """URLs that fetch nothing and name no file: data:, mailto:, javascript:, about:, blob:."""
    scheme = urllib.parse.urlsplit(url).scheme.lower()
    return scheme in ("data", "mailto", "javascript", "about", "blob", "tel")


class Page(html.parser.HTMLParser):
    """The ids of one page and the URLs it names, with the line of each."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids = set()
        self.base = None
        self.urls = []  # (line, tag, attribute, url, loaded)

    def handle_starttag(self, tag, attrs):
        line = self.getpos()[0]
        attrs = dict((k, v if v is not None else "") for k, v in attrs)
        if "id" in attrs:
            self.ids.add(attrs["id"])
        if tag == "a" and "name" in attrs:
            self.ids.add(attrs["name"])
        if tag == "base" and "href" in attrs:
            self.base = attrs["href"]
        for attribute in LOADED.get(tag, []):
            if attribute in attrs:
                # rel=canonical/alternate/… are not loaded; stylesheets, icons, preloads are.
                rel = attrs.get("rel", "").lower().split()
                loaded = not (tag == "link" and rel and set(rel) <= NOT_LOADED_RELS)
                for url in self.split(attribute, attrs[attribute]):
                    self.urls.append((line, tag, attribute, url, loaded))
        for attribute in FOLLOWED.get(tag, []):
            if attribute in attrs:
                self.urls.append((line, tag, attribute, attrs[attribute], False))
        for _, url in CSS_URL.findall(attrs.get("style", "")):
            self.urls.append((line, tag, "style", url, True))

    handle_startendtag = handle_starttag

    @staticmethod
    def split(attribute, value):
        if attribute == "srcset":
            return [part.strip().split()[0] for part in value.split(",") if part.strip()]
        return [value.strip()]


def parse(path):
    page = Page()
    with open(path, encoding="utf-8", errors="replace") as f:
        page.feed(f.read())
    page.close()
    return page


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "book"))
    if not os.path.isfile(os.path.join(root, "index.html")):
        print(f"linkcheck: no built book at {root} (run `mdbook build book` first)")
        return 1

    pages = {}
    for folder, _, files in os.walk(root):
        for name in files:
            if name.endswith(".html"):
                path = os.path.join(folder, name)
                pages[path] = parse(path)

    problems = []
    stylesheets = {}  # path -> the first page that links it

    def target_of(page_path, page, url):
        """The file a relative URL names, and its fragment."""
        parts = urllib.parse.urlsplit(url)
        path = urllib.parse.unquote(parts.path)
        if path == "":
            # "#id": this page (also under mdBook's <base href="/"> on 404.html, whose heading
            # anchors mean the page itself).
            target = page_path
        elif path.startswith("/"):
            # Site-absolute: the book is served at the site root (mdBook's site-url, "/").
            target = os.path.join(root, path.lstrip("/"))
        elif page.base and page.base.startswith("/"):
            # <base href="/…"> (mdBook's 404 page): relative to that folder of the site.
            target = os.path.join(root, page.base.lstrip("/"), path)
        else:
            target = os.path.join(os.path.dirname(page_path), path)
        target = os.path.normpath(target)
        if os.path.isdir(target):
            target = os.path.join(target, "index.html")
        return target, parts.fragment

    for page_path, page in sorted(pages.items()):
        rel = os.path.relpath(page_path, root)
        for line, tag, attribute, url, loaded in page.urls:
            where = f"{rel}:{line}: <{tag} {attribute}=\"{url}\">"
            if url == "" or is_skipped(url):
                continue
            if is_remote(url):
                if loaded:
                    problems.append(f"{where}: loads a resource from the network")
                continue
            target, fragment = target_of(page_path, page, url)
            if not target.startswith(root + os.sep) and target != root:
                problems.append(f"{where}: points outside the book")
                continue
            if not os.path.isfile(target):
                problems.append(f"{where}: no such file {os.path.relpath(target, root)}")
                continue
            if fragment and target.endswith(".html"):
                ids = pages[target].ids if target in pages else parse(target).ids
                if urllib.parse.unquote(fragment) not in ids:
                    problems.append(f"{where}: no id \"{fragment}\" in {os.path.relpath(target, root)}")
            if tag == "link" and target.endswith(".css"):
                stylesheets.setdefault(target, rel)

    # Stylesheets (and those they import): fonts and images must be local and present.
    seen = set()
    queue = sorted(stylesheets)
    while queue:
        css = queue.pop()
        if css in seen:
            continue
        seen.add(css)
        with open(css, encoding="utf-8", errors="replace") as f:
            text = CSS_COMMENT.sub("", f.read())
        urls = [u for _, u in CSS_URL.findall(text)] + [u for _, u in CSS_IMPORT.findall(text)]
        for url in urls:
            url = url.strip()
            where = f"{os.path.relpath(css, root)}: url({url})"
            if url == "" or is_skipped(url) or url.startswith("#"):
                continue
            if is_remote(url):
                problems.append(f"{where}: loads a resource from the network")
                continue
            path = urllib.parse.unquote(urllib.parse.urlsplit(url).path)
            target = os.path.normpath(os.path.join(os.path.dirname(css), path))
            if not os.path.isfile(target):
                problems.append(f"{where}: no such file {os.path.relpath(target, root)}")
            elif target.endswith(".css"):
                queue.append(target)

    for problem in problems:
        print(problem)
    checked = sum(len(p.urls) for p in pages.values())
    print(
        f"linkcheck: {len(pages)} pages, {checked} URLs, {len(seen)} stylesheets: "
        + ("ok" if not problems else f"{len(problems)} problem(s)")
    )
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
