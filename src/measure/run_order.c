#include "run_order.h"
#include <string.h>

void lx_run_order(const char *const *names, int n, unsigned long long *seq, int *order)
{
	int sorted[LX_RUN_ORDER_MAX];
	n = n < LX_RUN_ORDER_MAX ? n : LX_RUN_ORDER_MAX;
	for (int k = 0; k < n; k++) { /* by name (insertion: a few runs; stable) */
		int j = k;
		for (; j > 0 && strcmp(names[sorted[j - 1]], names[k]) > 0; j--)
			sorted[j] = sorted[j - 1];
		sorted[j] = k;
	}
	/* a Fisher-Yates shuffle of the sorted runs, from a 64-bit LCG */
	for (int k = n - 1; k > 0; k--) {
		*seq = *seq * 6364136223846793005ull + 1442695040888963407ull;
		int j = (int)((*seq >> 33) % (unsigned long long)(k + 1)), t = sorted[k];
		sorted[k] = sorted[j], sorted[j] = t;
	}
	memcpy(order, sorted, (size_t)n * sizeof *order);
}
