"""Small HTML helpers shared by the report's pages: escaping, the page frame with its inline style,
links, definition lists and tables."""
import functools
import html
import os

STYLE_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "report.css")


def esc(value):
    """Text for HTML; None as nothing, true/false as in the CSV files."""
    if isinstance(value, bool):
        value = "true" if value else "false"
    return html.escape("" if value is None else str(value), quote=True)


@functools.lru_cache(maxsize=None)
def style():
    with open(STYLE_FILE) as f:
        return f.read()


def page(title, body, script=""):
    """A whole page: no external resource, the style (and script) inline."""
    tail = f"<script>\n{script}\n</script>\n" if script else ""
    return (f"<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            f"<title>{esc(title)}</title>\n<style>\n{style()}</style>\n</head>\n<body>\n{body}\n{tail}</body>\n</html>\n")


def link(href, text):
    return f"<a href=\"{esc(href)}\">{esc(text)}</a>"


def status_badge(status):
    return f"<span class=\"st st-{esc(status)}\">{esc(status)}</span>"


def facts_list(items):
    """<dl> of (label, html) pairs; pairs with an empty value are left out."""
    cells = "".join(f"<dt>{esc(k)}</dt><dd>{v}</dd>" for k, v in items if v not in (None, ""))
    return f"<dl class=\"facts\">{cells}</dl>"


def table(header, rows, cls="plain"):
    """A plain table of text cells (escaped)."""
    head = "".join(f"<th>{esc(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{esc(c)}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table class=\"{cls}\"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def joined(values, empty="-"):
    values = [v for v in values if v]
    return esc(", ".join(values)) if values else empty
