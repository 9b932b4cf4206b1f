"""Rows of the README's benchmark table from scripts/bench/65-threads.sh: each parallel path on
1 and 2 threads and on 2 threads with another process busy on one core."""


def loaded(r):
    return [
        f"threads under load: {r['what']}",
        "1 thread / 2 threads / 2 threads + busy core",
        f"{float(r['threads_1_s']):.2f} / {float(r['threads_2_s']):.2f} / {float(r['loaded_threads_2_s']):.2f} s "
        f"(loaded / one thread = {float(r['loaded_over_quiet_1']):.2f})",
        "within 20 % of one thread",
    ]


SECTIONS = {"threads_loaded.csv": loaded}
