"""Text as a browser lays it out for VPython's page: the fonts, a label's box and leader,
a canvas's title and caption."""
