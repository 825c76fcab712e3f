int dummy_test_assembly;
