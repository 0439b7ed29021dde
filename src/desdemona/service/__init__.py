"""The on-line controller as a real-time service: a simulator host sends the vehicle's motion, the
service runs a session and sends setpoints to the motion system.

- :mod:`desdemona.service.protocol`: the UDP datagrams (``docs/protocol.md``), packed and unpacked;
- :mod:`desdemona.service.serve`: ``desdemona serve``, the session at a fixed rate, its watchdog and
  parking, and its log;
- :mod:`desdemona.service.hosts`: hosts for one computer (``desdemona host replay|jsbsim``);
- :mod:`desdemona.service.bridge`, :mod:`desdemona.service.flightgear`, :mod:`desdemona.service.xplane`:
  bridges from a running simulator's own UDP output, checked live (``desdemona host flightgear|xplane``);
- :mod:`desdemona.service.machine`: a stand-in for the motion system (``desdemona machine``), which
  checks every setpoint on its own;
- :mod:`desdemona.service.console`: the operator's live page and its buttons (``serve --console``).

The controller it calls (:mod:`desdemona.control.mpc`) is the one ``desdemona online`` runs, unchanged.
"""
