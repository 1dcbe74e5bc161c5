# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""HeatExponentialMap's precomputation reports its steps to a Python callable
and can be cancelled from it."""

import numpy as np
import pytest

import expmap


def test_steps_are_reported_in_order_and_end_with_done(elephant):
    _, V, F = elephant
    calls = []
    heat = expmap.HeatExponentialMap(V, F, progress=lambda step, fraction: calls.append(
        (step, fraction)))
    assert len(calls) >= 3
    assert calls[-1] == ("done", 1.0)
    fractions = [fraction for _, fraction in calls]
    assert fractions == sorted(fractions)
    assert 0 <= fractions[0] < 1
    assert all(isinstance(step, str) and step for step, _ in calls)
    # The callback changes nothing in the maps.
    plain = expmap.HeatExponentialMap(V, F)
    assert np.array_equal(heat.compute(7, fraction=0.05).uv, plain.compute(7, fraction=0.05).uv)


def test_an_exception_from_the_callback_cancels_the_precomputation(elephant):
    _, V, F = elephant

    class Cancelled(Exception):
        pass

    seen = []

    def cancel_at_second_step(step, fraction):
        seen.append(step)
        if len(seen) == 2:
            raise Cancelled(step)

    with pytest.raises(Cancelled):
        expmap.HeatExponentialMap(V, F, progress=cancel_at_second_step)
    assert len(seen) == 2


def test_progress_must_be_callable(elephant):
    _, V, F = elephant
    with pytest.raises(TypeError, match="progress must be callable"):
        expmap.HeatExponentialMap(V, F, progress=3)


def test_a_batch_reports_its_progress_and_ends_with_all_done(elephant):
    _, V, F = elephant
    calls = []
    batch = expmap.GeodesicPolarCoordinates(V, F).compute_many(
        range(200), vertices=30, threads=2, progress=lambda done, total: calls.append((done, total)))
    assert calls and calls[-1] == (200, 200)
    assert all(total == 200 and 0 < done <= 200 for done, total in calls)
    assert [done for done, _ in calls] == sorted(done for done, _ in calls)
    assert len(batch.sources) == 200 and not any(batch.errors)


def test_an_exception_from_a_batchs_callback_stops_it(elephant):
    _, V, F = elephant

    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        expmap.GeodesicPolarCoordinates(V, F).compute_many(range(50), vertices=30, progress=stop)
    with pytest.raises(TypeError, match="progress must be callable"):
        expmap.GeodesicPolarCoordinates(V, F).compute_many(range(5), vertices=30, progress="x")
