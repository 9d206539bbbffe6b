Web VPython 3.2
# An orbit, pasted from a web page: tab-indented lines mixed with spaces,
# a non-breaking space, attach_trail and attach_arrow.
G = 6.7e-11
earth = sphere(pos=vec(0, 0, 0), radius=6.4e6, color=color.blue)
craft = sphere(pos=vec(-10*earth.radius, 0, 0), radius=1e6, color=color.yellow)
mcraft = 15e3
craft.p = mcraft*vec(0, 3.27e3, 0)
attach_trail(craft, color=color.white)
attach_arrow(craft, "p", scale=5e3/mag(craft.p)*earth.radius/1e3, color=color.green)
dt = 60
t = 0
while t < 10*3600:
	rate(2000)
	r = craft.pos - earth.pos
	F = -G*6e24*mcraft/mag(r)**2*norm(r)
	craft.p = craft.p + F*dt
	craft.pos = craft.pos + craft.p/mcraft*dt
	if mag(r) < earth.radius:
	    print("crashed at t = " + t)
	    break
	t = t + dt
print("done at t = " + t + " s")
