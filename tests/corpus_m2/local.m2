-- tangent cones and local orders
R = QQ[x,y];
print toString tangentCone ideal(y^2 - x^2 - x^3)
print toString tangentCone ideal(x^3 - y^2 + x^4, x*y^3)
S = QQ[a,b,c];
print toString tangentCone ideal(a^2 - b^2 + c^3, a*b - c^2)
T = QQ[x,y, MonomialOrder => {Weights => {-1,-1}}, Global => false];
print toString gens gb ideal(x^2 + y^3 + x*y^5, x*y + x^4)
print dim ideal(x^2 + y^3, x*y)
A = QQ[x,y, MonomialOrder => {Weights => {-1,-1}, GRevLex}, Global => false];
print toString (1 + x + y^2 + x*y)
B = QQ[x,y, MonomialOrder => {Weights => {-1,-1}, Lex}, Global => false];
print toString (1 + x + y^2 + x*y + y)
