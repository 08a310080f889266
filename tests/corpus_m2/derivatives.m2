-- derivatives: by variables, by differential operators, of matrices
R = QQ[x,y,z];
print toString diff(x,x^7 + 4*x^3*y - 3*y)
print toString diff(x^2+y^2+z^2, y^2*z^2 - x^3 - 1)
print toString diff_x x^6
f = matrix{{x^2-y*z, x*y*z + z^4}, {x-1, 2*y^2+z^2-1}};
print toString diff(x^2-y*z,f)
print toString diff(vars R, (x+y-z)^2)
