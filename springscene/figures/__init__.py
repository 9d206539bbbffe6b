"""The wiki page's figures: plots, stills, a film strip, a GIF and a ``<gallery>`` snippet.

:func:`make_figures` writes, into one folder, for a config (``configs/wiki.toml``
is the page's scene):

==================  ===========================================================
``scene.png``       the scene at t = 0 (VTK, off-screen)
``position.*``      y(t) simulated against the closed form, residual below
``energy.*``        K, Us, Ug and E against time (and the heat, when damped)
``phase.*``         the phase portrait: displacement against velocity
``damped.*``        the damped y(t) inside its envelope A e^(-gamma t)
``resonance.*``     measured steady-state amplitude against the analytic A(omega)
``integrators.*``   energy error of Euler, Euler-Cromer, Verlet and RK4
``hooke.*``         the limits of Hooke's law: permanent set, force against stretch
``filmstrip.png``   one period in six stills
``oscillation.gif`` the oscillation in real time, looping, under 2 MB
``figures.wiki``    a MediaWiki ``<gallery>`` with a caption per figure
==================  ===========================================================

(``*`` is PNG and SVG.) A config without damping or drive gets a demo damping
(b = 0.1 kg/s) and a demo drive for the damped and resonance figures, and the
captions say so. The matplotlib figures are drawn with a fixed style, size and
dpi, and saved without dates, so the same config gives the same bytes every
run. Each ``*_figure`` function draws one figure from data passed in and returns
a :class:`matplotlib.figure.Figure`, so each can be tested on its own.

The modules, each importing only those below it:

================  ==============================================================
``wiki``          :func:`make_figures`: the steps, one per file, in order
``gallery``       a caption per figure and the ``<gallery>`` snippet
``plots``         the matplotlib figures (``*_figure``)
``media``         the film strip and the GIF, from the VTK scene
``oscillator``    the runs and closed forms the figures need (no drawing)
``notation``      how figures and captions write numbers
``matter``        the lattice figures (its own ``make_figures``)
``files``         the output folder; PNG, SVG and text written atomically
================  ==============================================================
"""

from .wiki import make_figures

__all__ = ["make_figures"]
