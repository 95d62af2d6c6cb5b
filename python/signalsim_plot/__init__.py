"""The plotting package behind signalsim-plot (run pictures and sweep heat maps)."""
