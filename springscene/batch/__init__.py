"""Many VPython programs at once: videos, pages, grades and an index (springscene batch, springscene grade)."""
