"""VPython programs run headless: VPython's interface, drawn off-screen, to video and a page.

``springscene vpython program.py --out video.mp4`` runs an unmodified VPython 7, VPython 6
or Web VPython program with :mod:`.api` standing in for ``vpython`` (and ``visual``). The
package is in rooms, each importing only the rooms below it (a ``layers`` contract in
``pyproject.toml``):

- :mod:`.run`: a program run, supervised in a child process, to its files;
- :mod:`.page`: the film of frames, the page laid out as VPython's, graphs as pictures,
  the HTML page;
- :mod:`.draw`: the VTK renderer; :mod:`.dialects`: the names and source leniencies of
  Web VPython and VPython 6;
- :mod:`.api`: what ``from vpython import *`` gives a program (the namespace, graphs,
  textures, attachments), on :mod:`.objects` (the 3D objects as data) and :mod:`.core`
  (vectors, the clock, canvases, controls, attribute declarations and checks);
- :mod:`.geometry`: objects to numpy meshes; :mod:`.text`: fonts and text layout.
"""
