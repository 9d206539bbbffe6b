"""What every VPython object and the program's namespace rest on: vectors, the program's
clock, canvases (the ``scene``, its camera and lights, the page's order), controls, and
how an object's attribute is declared and its values checked."""
