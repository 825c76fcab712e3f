int dummy_test_stepper;
