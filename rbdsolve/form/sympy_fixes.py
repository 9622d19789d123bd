"""Work-arounds for sympy bugs that a problem file can reach, each with its upstream
reference; applied once, when ``rbdsolve.form`` is imported (before any solving).

sympy#28621 (sympy 1.14, fixed upstream by PR #28624): ``factorint`` with a ``limit``
(as ``sqrt`` of a large integer calls it) can find a composite factor by Fermat's
method and then hand it to ``factor_cache.add``, which accepts primes only and raises
``ValueError: … is not a prime factor of …``. A file reaches it with numbers near the
limit of 1e±300 (``R/1e-300`` squared). The cache is only a cache: a composite factor
is left out of it, as the upstream fix does.
"""

from __future__ import annotations


def _patch_factor_cache() -> None:
    try:
        from sympy.ntheory import factor_ as ntheory
    except ImportError:  # pragma: no cover - an older sympy without the cache
        return
    cache = getattr(ntheory, "FactorCache", None)
    if cache is None or getattr(cache.add, "primes_only", False):
        return

    def add(self, n: int, factors) -> None:
        """Cache the prime factors among ``factors`` of ``n``; skip composite ones."""
        for p in sorted(factors, reverse=True):
            if 1 < p <= n and n % p == 0 and ntheory.isprime(p):
                self[n] = p
                n, _ = ntheory.remove(n, p)
                n = int(n)

    add.primes_only = True
    cache.add = add


_patch_factor_cache()
