"""`python -m robotfix.ament` runs `ament_robotfix`."""

from robotfix.ament import main

raise SystemExit(main())
