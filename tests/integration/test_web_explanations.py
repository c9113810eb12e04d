# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The web view's "why?" (issue 31) in a real browser: inferred facts show their justification."""

from playwright.sync_api import expect
# The web view's own fixtures (a node with its web port, a browser, a page) and helpers.
from test_web_view import browser, page, web_node  # noqa: F401
from test_web_view import ARTIFACTS, load, open_reference

LABEL = '<http://www.w3.org/2000/01/rdf-schema#label>'
NS = 'http://www.example.org/robotics#'
EXPLAINED_WITHIN_MS = 60_000


def test_an_inferred_type_and_value_say_why_with_linked_names_and_a_sentence(web_node, page):
    load(web_node, 'web_why', reasoner='HERMIT')
    from test_web_view import call
    answer = call(web_node, 'web_why', 'ADD AXIOM',
                  f'AnnotationAssertion({LABEL} <{NS}robot1> "the robot")')
    assert answer.success, answer.error_description
    open_reference(page, web_node, 'web_why', 'individuals')
    page.locator('tr[data-name="robot1"] td').first.click()
    detail = page.locator('#individual-detail')
    # Only inferred facts have a "why?": RobotInRoom and Agent, not the asserted Robot.
    expect(detail.locator('button.why')).to_have_count(2)
    detail.locator('a.inferred', has_text='RobotInRoom').locator('xpath=..').locator('button.why').click()
    box = detail.locator('.why-box')
    # Generous: the reasoner works on a shared, loaded machine (bench/explanations.py times it).
    expect(box).to_contain_text('justification 1', timeout=EXPLAINED_WITHIN_MS)
    expect(box.locator('li.axiom.asserted')).to_have_count(3)
    expect(box.locator('li.axiom')).to_contain_text(['kitchen Type Room', 'robot1 Type Robot',
                                                      'robot1 isIn kitchen',
                                                      'RobotInRoom EquivalentTo Robot and (isIn some Room)'])
    expect(box.locator('.why-sentence')).to_have_text(
        'the robot is a RobotInRoom because kitchen is a Room, the robot is a Robot, the robot isIn'
        ' kitchen and a RobotInRoom is exactly a Robot and (isIn some Room).')
    # Each name of an axiom links to its page (an individual's or a class's).
    kitchen = box.locator('a.entity', has_text='kitchen').first
    assert (kitchen.get_attribute('data-kind'), kitchen.get_attribute('data-iri')) == (
        'individual', NS + 'kitchen')
    room = box.locator('a.entity', has_text='Room').first
    assert (room.get_attribute('data-kind'), room.get_attribute('data-iri')) == ('class', NS + 'Room')
    # What docs/explanations.md shows (docs/images/web-view-why.png is copied from it).
    detail.screenshot(path=str(ARTIFACTS / 'web-view-why.png'))


def test_an_inferred_property_value_says_why(web_node, page):
    load(web_node, 'web_why_value', reasoner='HERMIT')
    open_reference(page, web_node, 'web_why_value', 'individuals')
    page.locator('tr[data-name="kitchen"] td').first.click()
    detail = page.locator('#individual-detail')
    expect(detail.locator('h3')).to_have_text('kitchen', timeout=EXPLAINED_WITHIN_MS)
    # kitchen contains robot1 (the inverse of isIn): an inferred value, explained the same way.
    detail.locator('a.inferred', has_text='robot1').locator('xpath=..').locator('button.why').click()
    expect(detail.locator('.why-box li.axiom')).to_contain_text(
        ['robot1 isIn kitchen', 'contains InverseOf isIn'], timeout=EXPLAINED_WITHIN_MS)


def test_an_inferred_link_of_the_class_tree_says_why(web_node, page):
    load(web_node, 'web_why_tree', reasoner='HERMIT')
    from test_web_view import call
    # Whatever isIn somewhere is an Agent (isIn's domain): Tracked is an Agent by inference only
    # (robotics.owl's own links are all stated, a named part of an EquivalentTo counting as such).
    answer = call(web_node, 'web_why_tree', 'ADD AXIOM', 'Tracked SubClassOf isIn some Location')
    assert answer.success, answer.error_description
    open_reference(page, web_node, 'web_why_tree', 'classes')
    tree = page.locator('#class-tree')
    link = tree.locator('span.class-name', has=page.locator('span.inferred[data-iri$="#Tracked"]')).first
    link.locator('button.why').click()
    expect(tree.locator('.why-box li.axiom')).to_contain_text(
        ['Tracked SubClassOf isIn some Location', 'isIn Domain Agent'], timeout=EXPLAINED_WITHIN_MS)
    # The asserted links have none.
    expect(tree.locator('span.class-name', has=page.locator('span.asserted[data-iri$="#Robot"]'))
           .locator('button.why')).to_have_count(0)
