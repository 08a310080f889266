-- the language: lists, functions, loops, comments, output suppression
R = QQ[x,y];
L = {1, 2, 3};
print toString L
print(#L)
print L#0
print L_2
print toString apply(L, i -> i^2)
print toString apply({x, y}, v -> v^2 + 1)
f = (a, b) -> a*b + 1;
print f(2, 3)
g = p -> p^2;
print toString g(x + y)
for i from 1 to 3 do print i
print toString (for i from 1 to 4 list i^2)
for p in {x, y} do print toString (p^3)
s = 0; for i in {1, 2, 3, 4} do s = s + i; print s
print toString {1..4}
print toString append(L, 4)
print toString join(L, {5, 6})
print (if #L > 2 then "long" else "short")
h = n -> if n <= 1 then 1 else n * h(n - 1);
print h(5)
-* a block
   comment *-
print toString last L
I = ideal(x, y^2);
print toString I_1
print toString (2 == 2, 1 < 0)
print (not (1 > 2) and 2 > 1)
print toString apply({ideal(x), ideal(x, y)}, dim)
