-- ideal arithmetic and Groebner bases
R = QQ[x,y,z];
I = ideal(x^2 - y, x*y - z);
J = ideal(x, z);
print toString I
print toString gens gb I
print toString groebnerBasis ideal(x^2 + y^2 - 1, x - y)
print toString (I + J)
print toString (J * ideal(x, y))
print toString (ideal(x^2, x*y) : ideal(x))
print toString (ideal(x^3*y, x*y^2) : x)
print toString saturate(ideal(x^2*y, x*y^3), ideal(x))
print toString saturate(ideal(x^2*y - x*z^2, x^3), x)
print toString intersect(ideal(x), ideal(y), ideal(x + y))
print toString intersect(ideal(x, y), ideal(y, z))
print toString eliminate({x}, I)
print toString eliminate(I, {x, y})
print toString eliminate({x, y}, ideal(x - y^2, y - z^3, x*y*z - 1))
print dim I
print codim I
print degree I
print dim ideal(x*y, x*z)
print degree ideal(x^2 + y^2 + z^2 - 1, x*y*z)
print dim ideal(1_R)
print (I == ideal(x^2 - y, z - x^3))
print (I == J)
print toString ((x^3 + y) % I)
print toString gens gb ideal(6*x - z, 1/2*y^2 - y)
