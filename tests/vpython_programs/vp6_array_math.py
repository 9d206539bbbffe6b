from visual import *
# VPython 6's vector functions take an N x 3 array and work row by row.
a = array([[3.0, 4, 0], [1, 2, 2], [0, 0, 0], [0, 0, 5]])
b = array([[1.0, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]])
print("mag", mag(a).tolist())
print("mag2", mag2(a).tolist())
print("norm", norm(a).tolist())
print("cross", cross(a, b).tolist())
print("cross_v", cross(a, vector(0, 0, 1)).tolist())
print("dot_v", dot(a, vector(1, 1, 1)).tolist())
print("dot_rows", dot(a, b).tolist())
print("one", mag(vector(3, 4, 0)), mag((0, 0, 2)), mag(a[0]))
wire = curve(pos=a)
print("wire", mag(wire.pos - vector(0, 0, 0)).tolist())
