-- minimal primes: over ZZ/p, in quotient rings, with CodimensionLimit, over a tower
R = ZZ/101[a..d];
assert(minprimes ideal(0_R) == {ideal(0_R)})
assert(minprimes ideal(1_R) == {})
assert(minprimes ideal(a^2-2*a*b+b^2) == {ideal(a-b)})
I0 = ideal(a^2-b^2, c*d);
C = minprimes I0;
A = R/I0;
assert( # minprimes ideal(0_A) == 4)
assert( all(minprimes ideal(0_A), I -> ring I === A))
assert(minprimes ideal(1_A) == {})
R1 = QQ[d,f,j,k,m,r,t,A,D,G,I,K];
I1 = ideal(I*K-K^2, r*G-G^2, A*D-D^2, j^2-j*t, d*f-f^2, d*f*j*k-m*r, A*D-G*I*K);
print (# minprimes(I1, CodimensionLimit => 6))
print (# minprimes I1)
R = QQ [a, b, c, d, e];
S = R [w_0, w_1, w_2, Join=>false];
J = ideal(b*w_0-c*w_1+d*w_2,a*w_0-b*w_1+c*w_2);
assert( intersect decompose J == J )
print "done"
