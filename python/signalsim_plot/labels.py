"""Keeping a picture's text labels apart: each label, in the order given, is moved along y (in steps of
the axes' data units) until its drawn box overlaps no label placed before it, then the axes' y range is
widened to hold every label. Works on the boxes the renderer draws, whatever the text and font."""


def _overlaps(a, b, pad):
    return a.x0 < b.x1 + pad and b.x0 < a.x1 + pad and a.y0 < b.y1 + pad and b.y0 < a.y1 + pad


def separate_labels(fig, ax, labels, step, max_moves=12, pad=2.0):
    """labels: [(matplotlib Text, direction +1 up / -1 down)]. Returns the number of labels moved."""
    renderer = fig.canvas.get_renderer()
    placed, moved = [], 0
    for text, direction in labels:
        x, y = text.get_position()
        box = text.get_window_extent(renderer)
        moves = 0
        while moves < max_moves and any(_overlaps(box, other, pad) for other in placed):
            moves += 1
            text.set_position((x, y + direction * step * moves))
            box = text.get_window_extent(renderer)
        moved += moves > 0
        placed.append(box)
    fit_labels(fig, ax, [t for t, _ in labels])
    return moved


def fit_labels(fig, ax, texts):
    """Widens ax's y range so that every text lies inside it."""
    renderer = fig.canvas.get_renderer()
    lo, hi = ax.get_ylim()
    to_data = ax.transData.inverted()
    for text in texts:
        box = text.get_window_extent(renderer)
        (_, y0), (_, y1) = to_data.transform([(box.x0, box.y0), (box.x1, box.y1)])
        lo, hi = min(lo, y0, y1), max(hi, y0, y1)
    ax.set_ylim(lo, hi)


def overlapping_pairs(fig, texts, pad=0.0):
    """Pairs (i, j) of texts whose drawn boxes overlap (the tests' check)."""
    renderer = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(renderer) for t in texts if t.get_visible() and t.get_text()]
    return [(i, j) for i in range(len(boxes)) for j in range(i + 1, len(boxes)) if _overlaps(boxes[i], boxes[j], pad)]
