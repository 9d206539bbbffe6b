GlowScript 1.1 VPython
# A GlowScript 1.1 lab: the canvas made with `display`, a graph with `gdisplay`,
# the caption written with jQuery's text() as GlowScript 1.x had it, JavaScript's
# `true`, and GlowScript 1's `wait` argument to sleep.
scene = display(title="old lab", width=400, height=300, background=color.white)
scene.caption.text("t = 0 <s>")
plot = gdisplay(title="height", xtitle="t", ytitle="y")
trace = gcurve(color=color.blue)
ball = sphere(pos=vec(-1, 1, 0), radius=0.15, color=color.red, make_trail=true)
floor = box(pos=vec(0, -0.05, 0), size=vec(3, 0.1, 0.5), color=color.green)
v = vec(1, 0, 0)
t = 0
dt = 0.01
sleep(0.1, wait)
while t < 1:
    rate(100)
    v.y = v.y - 9.8*dt
    ball.pos = ball.pos + v*dt
    if ball.pos.y < 0.15:
        v.y = abs(v.y)
    trace.plot(t, ball.pos.y)
    t = t + dt
scene.caption.append(" done")
print(version[0], scene.caption)
