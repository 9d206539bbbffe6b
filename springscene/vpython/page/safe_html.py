"""A program's title and caption HTML made safe to insert into the interactive page.

VPython inserts a canvas's title and caption as HTML, as it is. The interactive page is
a file a user may pass on, so it keeps what such HTML is for, formatting, and drops what
could run or fetch anything: :func:`sanitize` keeps the formatting tags of
:data:`ALLOWED_TAGS` with the harmless attributes of :data:`ALLOWED_ATTRIBUTES` (``href``
only to ``http``, ``https``, ``mailto`` or ``#``; ``style`` only without ``url(``,
``expression``, ``@import`` or ``position``), drops every ``on*`` attribute, drops ``<script>``,
``<style>``, ``<iframe>``, ``<object>``, ``<svg>`` and the like with all they hold, keeps
the text of any other tag, and keeps no comment but VPython's widget placeholders.
Text is written back escaped, so what is left is text and formatting only.
"""

from __future__ import annotations

import html
import re
from html.parser import HTMLParser

__all__ = ["sanitize", "ALLOWED_TAGS", "ALLOWED_ATTRIBUTES"]

ALLOWED_TAGS = frozenset(
    "a abbr b big blockquote br center code dd del div dl dt em font h1 h2 h3 h4 h5 h6 hr "
    "i ins kbd li mark ol p pre q s samp small span strike strong sub sup table tbody td "
    "tfoot th thead tr tt u ul var".split())
ALLOWED_ATTRIBUTES = frozenset(
    "align bgcolor border cellpadding cellspacing class color colspan face height href "
    "rowspan size style title valign width".split())
# tags dropped with everything inside them
_DROPPED_WHOLE = frozenset(
    "script style iframe frame frameset object embed applet noscript template svg math "
    "textarea select title head xmp plaintext noembed noframes".split())
_VOID = frozenset("br hr".split())
_SAFE_URL = re.compile(r"^\s*(https?:|mailto:|#)", re.IGNORECASE)
# what could fetch or run anything, and ``position`` (a title could lay a false page over
# the player)
_BAD_STYLE = re.compile(r"url\s*\(|expression\s*\(|@import|javascript:|behavior\s*:|\\|"
                        r"position\s*:", re.IGNORECASE)
_WIDGET_MARK = re.compile(r"^vpython-widget-\d+$")


class _Sanitizer(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.out: list[str] = []
        self.skipping: list[str] = []      # the dropped-whole tags we are inside

    def handle_starttag(self, tag: str, attrs) -> None:
        if tag in _DROPPED_WHOLE:
            if tag not in _VOID:
                self.skipping.append(tag)
            return
        if self.skipping or tag not in ALLOWED_TAGS:
            return
        kept = "".join(f' {name}="{html.escape(value, quote=True)}"'
                       for name, value in attrs if _attribute_ok(name, value))
        self.out.append(f"<{tag}{kept}>")

    def handle_startendtag(self, tag: str, attrs) -> None:
        self.handle_starttag(tag, attrs)
        if tag in self.skipping[-1:]:
            self.skipping.pop()

    def handle_endtag(self, tag: str) -> None:
        if tag in _DROPPED_WHOLE:
            if tag in self.skipping:
                while self.skipping and self.skipping.pop() != tag:
                    pass
            return
        if not self.skipping and tag in ALLOWED_TAGS and tag not in _VOID:
            self.out.append(f"</{tag}>")

    def handle_data(self, data: str) -> None:
        if not self.skipping:
            self.out.append(html.escape(data, quote=False))

    def handle_comment(self, data: str) -> None:
        if not self.skipping and _WIDGET_MARK.match(data):
            self.out.append(f"<!--{data}-->")


def _attribute_ok(name: str, value: str | None) -> bool:
    if value is None or name not in ALLOWED_ATTRIBUTES:
        return False
    if name == "href":
        return bool(_SAFE_URL.match(value))
    if name == "style":
        return not _BAD_STYLE.search(value)
    return True


def sanitize(markup: str) -> str:
    """``markup`` (a program's HTML) with only text and formatting left (module docstring).

    >>> sanitize('<b>k</b> = 5<script>alert(1)</script> <a href="javascript:x()">go</a>')
    '<b>k</b> = 5 <a>go</a>'
    """
    parser = _Sanitizer()
    parser.feed(str(markup))
    parser.close()
    return "".join(parser.out)
