"""The orchestrator graph as LangGraph itself sees it: edges, reachability, the gates to EXECUTE."""

from __future__ import annotations

import subprocess
import sys
from collections import defaultdict

import pytest

from sdi.orchestrator import RoutingError, build_graph
from sdi.orchestrator.graph import NODES, ROUTES, _router

PAPER_PHASES = ("plan", "design", "inspect", "review", "pre_execute", "execute", "replan")


def edges() -> dict[str, set[str]]:
    drawn = build_graph().compile().get_graph()
    out: dict[str, set[str]] = defaultdict(set)
    for e in drawn.edges:
        out[e.source].add(e.target)
    return out


def reachable(graph: dict[str, set[str]], without: str = "") -> set[str]:
    seen, todo = {"__start__"}, ["__start__"]
    while todo:
        for nxt in graph[todo.pop()]:
            if nxt != without and nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen


def test_every_phase_is_reachable_and_can_end():
    graph = edges()
    assert set(NODES) | {"__start__", "__end__"} == reachable(graph)
    assert set(PAPER_PHASES) <= reachable(graph)
    for node in NODES:  # from every phase the run can still finish
        assert "__end__" in reachable({**graph, "__start__": {node}}), node


def test_every_path_to_execute_passes_the_inspector_and_the_approval():
    graph = edges()
    for gate in ("inspect", "review", "pre_execute", "confirm"):
        assert "execute" not in reachable(graph, without=gate), gate
    into_execute = {src for src, targets in graph.items() if "execute" in targets}
    assert into_execute == {"confirm"}
    into_confirm = {src for src, targets in graph.items() if "confirm" in targets}
    assert into_confirm == {"pre_execute"}


def test_fixed_edges_where_the_flow_is_fixed():
    drawn = build_graph().compile().get_graph()
    fixed = {(e.source, e.target) for e in drawn.edges if not e.conditional}
    assert ("__start__", "plan") in fixed and ("design", "inspect") in fixed
    conditional = {e.source for e in drawn.edges if e.conditional}
    assert conditional == set(ROUTES)  # branch points only, each with its path map


def test_an_unknown_route_is_an_error_not_the_end():
    route = _router("inspect", ROUTES["inspect"])
    assert route({"phase": "review"}) == "review"
    with pytest.raises(RoutingError, match="revue"):
        route({"phase": "revue"})
    with pytest.raises(RoutingError, match="'end'"):  # the Inspector cannot end a run quietly
        route({"phase": "end"})


def test_sdi_graph_prints_langgraphs_own_mermaid():
    proc = subprocess.run(
        [sys.executable, "-m", "sdi.cli", "graph"], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 0, proc.stderr
    text = proc.stdout
    assert text.lstrip("-\n").startswith("config:") or "graph TD;" in text
    for line in ("__start__ --> plan;", "design --> inspect;", "confirm -.-> execute;"):
        assert line in text
