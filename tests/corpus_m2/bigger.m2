-- larger Groebner bases: katsura4 over QQ and ZZ/32003, a Lex elimination, explicit GRevLex
R = QQ[x,y,z,t, MonomialOrder => GRevLex];
K = ideal(x + 2*y + 2*z + 2*t - 1, x^2 + 2*y^2 + 2*z^2 + 2*t^2 - x, 2*x*y + 2*y*z + 2*z*t - y, y^2 + 2*x*z + 2*y*t - z);
print toString gens gb K
print toString(dim K, degree K)
S = ZZ/32003[x,y,z,t];
print toString gens gb ideal(x + 2*y + 2*z + 2*t - 1, x^2 + 2*y^2 + 2*z^2 + 2*t^2 - x, 2*x*y + 2*y*z + 2*z*t - y, y^2 + 2*x*z + 2*y*t - z)
T = QQ[a,b,c, MonomialOrder => Lex];
print toString gens gb ideal(a^2 + b^2 + c^2 - 1, a*b - c, b^3 - a)
U = QQ[p,q,r,s, MonomialOrder => Eliminate 2];
print toString gens gb ideal(p - r^2, q - r*s, p*q - s^3)
print toString eliminate({p, q}, ideal(p - r^2, q - r*s, p*q - s^3))
