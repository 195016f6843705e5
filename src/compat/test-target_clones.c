/*
 * test-target_clones.c - configure: functions built twice, for AVX2
 * and the baseline, the CPU choosing at load time (an ifunc: glibc on
 * x86-64 has them; mingw-w64 and musl do not).
 */
__attribute__((target_clones("avx2", "default")))
static double
sum(const double *a, int n)
{
	double s = 0;

	for (int i = 0; i < n; i++)
		s += a[i];
	return s;
}

int
main(void)
{
	static const double a[4] = { 1, 2, 3, 4 };

	return sum(a, 4) != 10;
}
