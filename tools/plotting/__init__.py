"""Plotting helpers for tools/plot (run pictures and sweep heat maps)."""
