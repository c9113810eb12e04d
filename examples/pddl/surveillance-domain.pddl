; Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
; The surveillance robot of the tutorial (examples/surveillance_demo.py) as a STRIPS domain with
; typing: it moves between connected locations, every location it enters counts as visited,
; and it recharges at a charging station. Moving spends the charge, so a plan that must end
; recharged recharges last. Problems come from ARMOR: QUERY PDDL PROBLEM with
; surveillance-mapping.yaml (docs/pddl.md).
(define (domain surveillance)
  (:requirements :strips :typing)
  (:types robot location)
  (:predicates
    (at ?r - robot ?l - location)
    (connected ?from - location ?to - location)
    (charging-station ?l - location)
    (visited ?l - location)
    (recharged ?r - robot))
  (:action move
    :parameters (?r - robot ?from - location ?to - location)
    :precondition (and (at ?r ?from) (connected ?from ?to))
    :effect (and (not (at ?r ?from)) (not (recharged ?r)) (at ?r ?to) (visited ?to)))
  (:action recharge
    :parameters (?r - robot ?l - location)
    :precondition (and (at ?r ?l) (charging-station ?l))
    :effect (recharged ?r)))
