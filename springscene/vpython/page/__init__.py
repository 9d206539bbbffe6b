"""What a VPython program shows besides its canvases, as pictures and as a page: the frames
of its video (the page laid out as VPython's, or the first canvas alone), its graphs drawn
with matplotlib, and the HTML page written beside the video."""
