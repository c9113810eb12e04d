# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The sample parameters file loads with --params-file into a real node (issue 11 item 12):
every value in it has the type the node declares, and the node uses them."""

import yaml

from conftest import REPO, start_node

SAMPLE = REPO / 'armor_service' / 'config' / 'armor.params.yaml'
NAMESPACE = '/params_file'


def _parameters(names):
    """The node's values of names, read through its get_parameters service."""
    import rclpy
    from rcl_interfaces.srv import GetParameters
    from rclpy.parameter import parameter_value_to_python
    node = rclpy.create_node('params_file_test')
    try:
        client = node.create_client(GetParameters, f'{NAMESPACE}/armor_service/get_parameters')
        assert client.wait_for_service(timeout_sec=60)
        future = client.call_async(GetParameters.Request(names=list(names)))
        rclpy.spin_until_future_complete(node, future, timeout_sec=60)
        return {n: parameter_value_to_python(v) for n, v in zip(names, future.result().values)}
    finally:
        node.destroy_node()


def test_the_sample_parameters_file_loads_and_is_used(tmp_path, armor):
    sample = yaml.safe_load(SAMPLE.read_text())['/**']['ros__parameters']
    # The test's own preload and state directory (given by start_node) are kept.
    changed = {name: value for name, value in sample.items()
               if name not in ('state_dir', 'preload_file', 'preload_reference')}
    changed.update(strict_names=True, checkpoint_every_changes=500)
    params = tmp_path / 'my.params.yaml'
    params.write_text(yaml.safe_dump({'/**': {'ros__parameters': changed}}))
    node = start_node(tmp_path, '--params-file', str(params), namespace=NAMESPACE)
    try:
        from armor_client import ArmorTransport, directive
        with ArmorTransport(namespace=NAMESPACE, service_wait_s=120) as transport:
            unknown = transport.call(directive('t', 'robotics', 'QUERY', 'IND', 'CLASS',
                                               args=['Rooom']), timeout_s=120)
        # The file's own values, of the declared types (a wrong type stops the node at start).
        read = _parameters(list(changed))
    finally:
        node.stop()
    assert unknown.exit_code == 224, (unknown.exit_code, unknown.error_description, node.log())
    for name, value in read.items():
        assert value == changed[name], (name, value, changed[name])
