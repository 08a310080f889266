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
gg = u^3 + 99*v;
print toString (gg[1000,3])
print toString (gg[v,u])
RR1 = QQ[e_1, e_2, e_3, e_4, g_1, g_2, g_3, g_4, r];
I = ideal(r^2-3,e_2^2-3*e_3^2,e_1^2+6*e_3^2+e_4^2);
RR2 = QQ[support I];
I1 = sub(I,RR2);
print toString I1
print toString gens RR2
