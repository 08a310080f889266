-- Submodules of free modules, syzygies, kernels, images, cokernels, free resolutions, Betti tables.
R = QQ[x,y,z];
M = matrix {{x, y, z}};
print toString gens gb M
N = matrix {{x, y}, {y, z}};
print toString gens gb N
print toString gens gb matrix {{x^2, x*y}, {y^2, z^2}}
print toString gens gb matrix {{x, y}, {x, z}}
print toString syz matrix {{x^2, x*y, y^2}}
print toString kernel matrix {{x, y}}
print toString (ker M == image syz M)
print toString (image syz M == image matrix {{-y, 0, -z}, {x, -z, 0}, {0, y, x}})
print toString ker N
print toString image M
print toString coker M
print toString mingens image matrix {{x, y, x+y}}
print toString trim image matrix {{x^2, y^2, x*y, x^2+y^2}}
print toString prune image matrix {{x, y}}
print toString prune coker matrix {{1, x}, {0, y}}
print toString (prune coker M == coker matrix {{z, y, x}})
print toString rank coker matrix {{x, y}}
print toString rank image N
C = res ideal(x, y, z);
print toString betti C
print toString length C
print toString C_2
print toString rank C_3
print toString betti res ideal(x*y, y*z, x*z)
print toString betti gens ideal(x, y)
print toString pdim coker gens ideal(x, y)
S = ZZ/101[a,b,c,d];
print toString betti res ideal(a*c-b^2, a*d-b*c, b*d-c^2)
print toString betti res ideal(a^2, b^2, c^2, d^2)
print toString betti res ideal(a^3, a^2*b, b^3, a*c^2, c^3-d^3)
print toString betti res coker matrix {{a, b, c}, {b, c, d}}
print toString betti res image matrix {{a, b, c}, {b, c, d}}
print toString betti res(ideal(a, b, c), LengthLimit => 2)
print toString pdim coker matrix {{a, b, c}, {b, c, d}}
M = coker matrix {{a, b}, {c, d}};
print toString codim M
print toString dim M
print toString ann M
print toString ann coker matrix {{a, b, c}, {b, c, d}}
print toString ann image matrix {{a, b}}
I = ideal(a^2, b^2);
print toString trim(S^1/I)
print toString dim(S^1/I)
print toString prune(S^1/I)
print toString betti res(S^1/I)
N = coker matrix {{x, y}, {y, z}};
print toString ambient N
print toString relations N
print toString cover image matrix {{x, y}}
print toString super image matrix {{x, y}}
print toString isFreeModule N
print toString isFreeModule R^2
print toString isHomogeneous N
f = matrix {{x, y}};
print toString (image modulo(f, matrix {{x^2, y^2}}) == image map(source f, , {{x, 0, -y}, {0, y, x}}))
print toString gens N
print toString numgens image matrix {{x, y, z}}
T = QQ[w,x,y,z];
f = map(T^1, T^3, matrix {{x^2-w*y, x*y-w*z, x*z-y^2}});
print toString ideal image f
U = QQ[a..d];
print toString syz matrix {{a, b, c, d}}
print toString syz matrix {{a, b}, {c, d}}
print toString syz matrix {{a, b, c}, {b, c, d}}
print toString modulo(matrix {{a, b}}, matrix {{a^2, b^2}})
