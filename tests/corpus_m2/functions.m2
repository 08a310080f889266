-- constructors and functions on polynomials, ideals, rings and ring maps
R = QQ[x,y,z];
print toString monomialIdeal(x^2, y*x, x^3, z)
print toString monomialIdeal ideal(x^2+y, y^3)
print toString vars R
print toString genericMatrix(R, 3, 1)
print toString monomialCurveIdeal(R, {1,2})
print toString ideal "x2,y"
print toString trim ideal(x^2, x^2+y, y)
print toString mingens ideal(x^2, x^2+y, y)
print numgens R
print toString support(x^2*z+1)
print toString terms(3*x^2*z+y-1)
print toString leadTerm(3*x^2*z+y-1)
print toString leadMonomial(3*x^2*z+y-1)
print toString leadCoefficient(3*x^2*z+y-1)
print toString leadTerm ideal(x^2-y, x*y-z)
print isHomogeneous ideal(x^2-y*z)
print isHomogeneous (x^2-y)
print toString homogenize(x^2-y, z)
print toString homogenize(ideal(x^2-y, x^3-1), z)
print toString substitute(x^2+y, {x => y+1})
S = QQ[a,b];
f = map(S, R, {a, b, a+b});
print toString f(x^2+z)
print toString f ideal(x, y-z)
print toString ring (a+b)
print toString kernel f
print toString resultant(x^2-y, x^3-z, x)
print toString discriminant(x^2+y*x+z, x)
print toString sylvesterMatrix(x^2-y, x-z, x)
print toString singularLocus ideal(y^2-x^3)
print numcols vars R
