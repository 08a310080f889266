-- ideal operators keep the generators as Macaulay2 lists them
R = QQ[x,y,z];
I = ideal(x, y^2);
print toString (I^2)
print toString (I + ideal(x, 0_R))
print toString (I * I)
print toString ideal(x, 0_R, x)
print toString (x*I)
print toString (ideal(x^2-y) + ideal(x^2-y))
print toString (-x^2 + 3)
print toString ((x+y)^3)
print toString (2*I)
print toString ideal(2*x, 4*y)
print toString (gens gb ideal(2*x, 4*y))
