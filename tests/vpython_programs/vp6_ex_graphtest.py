from visual.graph import *
# Stands for VPython 6's examples/graphtest.py: graphs of functions and a histogram.
# Features: only `from visual.graph import *` (which also gave cos, exp, arange),
# gdisplay(xtitle=, ytitle=, title=, x=, y=), gcurve, gvbars(delta=), gdots,
# ghistogram(bins=) fed twice with accumulate=1, plot(pos=) and plot(data=).
response = gdisplay(xtitle='t', ytitle='x')
decay = gcurve(color=color.green)
bars = gvbars(delta=0.4, color=color.blue)
marks = gdots(color=color.orange)
for t in arange(0, 20, 0.5):
    decay.plot(pos=(t, 4*exp(-0.1*t)*cos(0.8*t)))
    bars.plot(pos=(t, 2*sin(0.3*t)))
    marks.plot(pos=(t, 3*cos(0.2*t)))
tally = gdisplay(title='Tally', x=0, y=300, width=600, height=300)
scores = ghistogram(bins=arange(0, 50, 10), color=color.red)
scores.plot(data=[3, 14, 27, 31, 45, 12, 18])
scores.plot(data=[8, 22, 41], accumulate=1)
