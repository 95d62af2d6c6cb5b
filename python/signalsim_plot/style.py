"""Colours and names shared by the run pictures."""

BLINKER_COLORS = {"left": "#1f77b4", "right": "#ff7f0e", "hazard": "#d62728"}
LIGHT_COLORS = {"G": "#1a9641", "g": "#78c679", "y": "#f0c000", "Y": "#f0c000", "r": "#d7191c",
                "u": "#fd8d3c", "s": "#a6d96a", "o": "#bdbdbd", "O": "#bdbdbd"}
LIGHT_NAMES = {"G": "green (priority)", "g": "green", "y": "yellow", "Y": "yellow", "r": "red",
               "u": "red-yellow", "s": "green arrow, stop first", "o": "off (blinking)", "O": "off"}
DECISION_COLORS = {"pass": "#4daf4a", "stop": "#e41a1c", "emergency_stop": "#984ea3"}
STOP_STATES = ("y", "Y", "r", "u")  # the states the judge may stop for (a yellow or a red was met)
