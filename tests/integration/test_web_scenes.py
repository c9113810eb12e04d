# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The web view's Scenes tab (issue 32) in a real browser: the learned scene classes as a
hierarchy, each defined in words, and the last scenes with their recognitions explained; a scene
sent over ROS appears without a reload."""

from playwright.sync_api import expect
# The web view's own fixtures (a node with its web port, a browser, a page) and helpers.
from test_web_view import browser, page, web_node  # noqa: F401
from test_web_view import call, open_reference, still_the_same_document

SIT = 'http://www.emarolab.it/sit/simple'
TWO_SPHERES = 'SPHERE 0 0 0; SPHERE 0.8 0 0.8'
SPHERE_AND_CONE = 'SPHERE 0 0 0; CONE -0.8 -0.8 0 0 0 1'
ALL_THREE = 'SPHERE 0 0 0; CONE -0.8 -0.8 0 0 0 1; SPHERE 0.8 0 0.8'
TWO_CONES = 'CONE 0 0 0 0 0 1; CONE 1 0 0 0.5 0.5 0'


def scene(node, reference, elements, threshold='0.9'):
    answer = call(node, reference, 'SIT SCENE', threshold, '0.03', '0.05', elements)
    assert answer.success, answer.error_description
    return answer.queried_objects


def test_learned_scenes_form_a_hierarchy_in_words_and_recognitions_are_explained(
        web_node, page):  # noqa: F811
    reference = 'web_scenes'
    assert call(web_node, reference, 'CREATE', SIT, 'false', 'PELLET', 'false').success
    for elements in (TWO_SPHERES, SPHERE_AND_CONE, ALL_THREE):
        scene(web_node, reference, elements)
    open_reference(page, web_node, reference, 'scenes')

    tree = page.locator('#scene-classes')
    # SCENE-3 contains the other two: it is listed under each of them.
    for parent in ('SCENE-1', 'SCENE-2'):
        nested = tree.locator(f'li[data-scene="{parent}"] li[data-scene="SCENE-3"]')
        expect(nested).to_have_count(1)
    expect(tree.locator('li[data-scene="SCENE-1"] > .scene-definition li').first).to_be_visible()
    expect(tree.locator('li[data-scene="SCENE-1"] > .scene-definition')).to_contain_text(
        'at least 1 SPHERE below a SPHERE')
    expect(tree.locator('li[data-scene="SCENE-2"] > .scene-definition')).to_contain_text(
        'at least 1 CONE left of a SPHERE')

    recent = page.locator('#scene-recent .scene-card').first
    expect(recent).to_contain_text('learned')
    expect(recent).to_contain_text('cardinality 12')
    why = recent.locator('details.scene-recognition', has_text='SCENE-1')
    why.locator('summary').click()
    explanation = why.locator('table.scene-explanation')
    expect(explanation).to_contain_text('at least 1 SPHERE below a SPHERE')
    expect(explanation).to_contain_text('SPHERE#1 below SPHERE#3')
    expect(explanation).to_contain_text('1 of at least 1')

    # A scene sent meanwhile shows up on the open page, with its definition in words.
    scene(web_node, reference, TWO_CONES)
    expect(tree.locator('li[data-scene="SCENE-4"]')).to_contain_text(
        'at least 2 CONE along X', timeout=30_000)
    assert still_the_same_document(page)


def test_a_reference_without_scenes_says_so(web_node, page):  # noqa: F811
    reference = 'web_no_scenes'
    assert call(web_node, reference, 'CREATE', SIT, 'false', 'PELLET', 'false').success
    open_reference(page, web_node, reference, 'scenes')
    expect(page.locator('#scene-classes')).to_contain_text(
        'No scene learned in this reference yet')
    expect(page.locator('#scene-recent')).to_contain_text('No scene shown to this reference')
