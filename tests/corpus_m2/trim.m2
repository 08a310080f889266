-- trim and mingens as Macaulay2, drop, vars, join, codim, MonomialSize overflow
R = ZZ/101[a,b,c];
I = ideal(a^2,a*b-2,c^4,a*c-1,a*c-1);
print toString trim I
print toString mingens I
S = QQ[x,y];
print toString trim ideal(x^2, x^2+y, y)
print toString trim ideal(x^3-y, x*y-1, y^2-x^2)
print toString drop({a,b,c,d,e,f,g}, {3,1})
print toString drop({a,b,c,d,e,f,g}, {4,-1})
print toString vars(0..3)
print toString join({1},{2},(3,4))
print codim S
print codim (S/ideal(x))
C = QQ[a..d,MonomialSize=>8,MonomialOrder=>GRevLex];
print (try a^(2^15-1) else "failed")
print toString (a^(2^7-1))
print toString ideal monomialIdeal(a^2, a*b)
print toString vars(52)
print toString take("Hello", 5)
R5 = ZZ/101[x,y,z];
f = x^3+3*y^2*z+2*z^3;
print toString substitute(f,{x=>-1,y=>2,z=>5})
