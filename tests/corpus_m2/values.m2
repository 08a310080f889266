-- maps and rings as values, strings as sequences, L / f
R = QQ[x,y,z];
print toString leadTerm matrix{{x^2+y, y-z}}
S = QQ[a,b];
f = map(S, R, {a, b, a+b});
print toString target f
print toString source f
print toString matrix f
print toString coefficientRing R
print toString baseName x
print toString substitute(x^2+y, matrix{{a, b, a}})
print toString apply("abc", identity)
print toString ({1,2}/(i->i+1))
print toString (ZZ/101[t_0..t_4])
Q = R/ideal(x^2, y);
print toString ideal Q
T2 = QQ[u,v];
g = u^3 + 99*v;
print toString (g[1000,3])
print toString (g[v,u])
