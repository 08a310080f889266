-- rings and monomial orders: polynomials print with the ring's order
R = QQ[x,y,z];
f = x^3 + y^2*z + x*z^2 - 1/2*x*y + 7;
print toString f
S = QQ[x,y,z, MonomialOrder => Lex];
print toString (x^3 + y^2*z + x*z^2 - 1/2*x*y + 7)
T = QQ[x,y,z, MonomialOrder => GLex];
print toString (x*z^2 + y^3 + x^2*y + z)
U = QQ[a,b,c,d, MonomialOrder => Eliminate 2];
print toString (a + b^3 + c^5*d + d^2)
V = QQ[a,b,c,d, MonomialOrder => {GRevLex => 2, GRevLex => 2}];
print toString (a + b^2 + c^3 + d^4 + a*d)
W = QQ[a,b,c, MonomialOrder => {Weights => {1,2,3}}];
print toString (a^5 + b^2 + c + a*b)
P = QQ[a,b,c, MonomialOrder => {Lex => 1, GRevLex => 2}];
print toString (a + b^2 + c^3 + a*c)
F = ZZ/32003[u_1..u_5];
print toString (16002*u_1 - u_2^2 + 32002 + u_5*u_3)
print toString gens gb ideal(2*u_1 - u_2, u_3^2 - 3*u_4)
L = QQ[s,t, MonomialOrder => {Weights => {-1,-1}}, Global => false];
print toString (s + t^2 + 1 + s^3*t)
C = QQ[x,y,z, MonomialOrder => {Weights => {1,1,0}, Weights => {0,0,1}}];
print toString (x^2 + z^5 + x*y + y*z)
