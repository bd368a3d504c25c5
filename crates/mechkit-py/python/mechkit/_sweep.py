"""``mechkit.sweep``: on this machine's cores, or on a Dask cluster when given a client.

On a cluster the sweep is split into shards (``--shard K/N``: run ``i`` is in shard
``i % N + 1``, so every shard samples the whole range and shards cost about the same), a few
per worker thread so that a fast worker takes more of them. Each shard is one task that runs
``mechkit``'s sweep on its worker from the scenario's TEXT (read here: a path may not exist
on a worker) and returns its table as bytes, every number to the bit. The parts are merged
here by the library's merge (the checks of ``mechkit sweep-merge``), so the result is the
``SweepResult`` the sweep without a client gives, and ``to_csv()`` is the command's
``sweep.csv`` byte for byte. mechkit must be installed on the workers (on a ``LocalCluster``
it is).
"""

import time
import uuid

from . import _native
from ._native import MechkitError

#: How often (s) the client looks at the shards while it waits.
POLL = 0.05

#: Shards per worker thread: enough for a slow worker's shards to be taken up by the others,
#: few enough that each task runs many runs.
SHARDS_PER_THREAD = 4


def sweep(
    scenario,
    set=None,
    *,
    client=None,
    random=None,
    seed=None,
    shard=None,
    threads=None,
    plot=None,
    **params
):
    """Runs ``mechkit sweep`` in memory and returns a ``SweepResult``.

    ``scenario`` is a ``mechkit.Scenario`` or a scenario file's path. The swept constants
    are ``set``, a string or a list of strings as ``--set`` takes them (``"v0=0:5:51"``,
    ``"k=1,2,4"``, ``"v0=0 km/h:18 km/h:51"``) or a dict of them by name
    (``{"v0": "0:5:51", "k": [1, 2, 4]}``), and keyword arguments: ``v0="0:5:51"``,
    ``k=[1, 2, 4]``, ``m=2.0`` (numbers in SI); the last varies fastest. ``random=N`` draws
    N points instead of the grid (seeded by ``seed``), ``shard="K/N"`` runs one slice of it,
    ``threads`` workers run it (all cores by default; the table does not depend on it).
    ``plot`` is the plot every run records for the overlay: None for the scenario's first
    plot (as the command), a spec, or False. The GIL is released while it runs; Ctrl-C
    stops the runs in flight and raises KeyboardInterrupt.

    ``client``, a ``dask.distributed.Client``, runs the sweep on its cluster instead, in
    shards (``pip install 'mechkit[dask]'``); the result is the same, to the bit. Ctrl-C
    cancels the shards not yet done; a run that fails on a worker raises its
    ``MechkitError`` (naming the run) here.
    """
    if client is None:
        return _native.sweep(
            scenario,
            set,
            random=random,
            seed=seed,
            shard=shard,
            threads=threads,
            plot=plot,
            **params
        )
    _check_client(client, shard, threads)
    plan = _native._sweep_plan(scenario, set, random=random, seed=seed, plot=plot, **params)
    runs = plan.pop("runs")
    slots = sum(client.nthreads().values())
    n = max(1, min(runs, SHARDS_PER_THREAD * max(slots, 1)))
    args = (plan["name"], plan["text"], plan["set"], plan["random"], plan["seed"], plan["plot"])
    tag = uuid.uuid4().hex[:12]
    futures = [
        client.submit(
            _run_shard, *args, "{}/{}".format(k, n), key="mechkit-sweep-{}-{}".format(tag, k)
        )
        for k in range(1, n + 1)
    ]
    try:
        parts = _gather(client, futures)
    except BaseException:
        # Ctrl-C, or a run that failed: the other shards are not waited for
        client.cancel(futures)
        raise
    return _native._sweep_merge(*args, parts)


def _check_client(client, shard, threads):
    """Refuses a client that is not a ``dask.distributed.Client``, and the options that a
    cluster decides."""
    try:
        from distributed import Client
    except ImportError:
        raise MechkitError(
            "client= runs the sweep on a Dask cluster, and dask.distributed is not installed\n"
            "  = hint: pip install 'mechkit[dask]', or leave client out to run on this "
            "machine's cores"
        ) from None
    if not isinstance(client, Client):
        raise TypeError(
            "client is a {}: give a dask.distributed.Client, or None to run on this "
            "machine's cores".format(type(client).__name__)
        )
    if shard is not None:
        raise MechkitError(
            "shard goes without client: on a cluster the sweep is split into shards for you\n"
            "  = hint: leave shard out, or leave client out to run one shard here"
        )
    if threads is not None:
        raise MechkitError(
            "threads goes without client: on a cluster each worker runs as many shards at "
            "once as it has threads\n"
            "  = hint: leave threads out, and set the workers' threads on the cluster "
            "(LocalCluster(threads_per_worker=...))"
        )


def _gather(client, futures):
    """The shards' parts, once all are done or one failed (its error raised). Waits in short
    sleeps, not in one blocking call, so that Ctrl-C is seen at once."""
    while not all(f.done() for f in futures):
        if any(f.status == "error" for f in futures):
            break
        time.sleep(POLL)
    return client.gather(futures)


def _run_shard(name, text, sets, random, seed, plot, shard):
    """On a worker: the shard ``shard`` ("K/N") of the sweep, its table as bytes."""
    return _native._sweep_part(name, text, sets, random, seed, plot, shard)
