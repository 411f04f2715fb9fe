"""Issue 14: host command ids never repeat one the machine may still remember.

The machine answers a repeated id from its cache without carrying it out (a retry).
Ids that restarted at 1 for each session let a new session's command, after a
reconnect or a restart of the program, be taken for a retry of an old one: it got the
old command's cached answer and was never carried out.
"""

from app.comm.commands import CommandQueue
from app.comm.listener import SessionState
from app.comm.session import Session
from tests.comm.scripted import Recorder
from tests.comm.simlink import SimLink


def test_a_new_session_is_not_answered_from_the_old_sessions_cache():
    link = SimLink(check=True)  # SET CHECK 1: the machine remembers its id and answer
    assert link.sim.cnc.check_mode
    link.session.detach("reconnect")
    link.rec = Recorder()
    link.session = Session(None, link.rec, clock=lambda: link.sim.clock.now, ids=link.session.commands.ids)
    link.attach()
    assert link.run_until(lambda: link.session.state is SessionState.READY, 2.0)
    result = link.command("SET", "CHECK", 0)
    assert result.ok
    assert not link.sim.cnc.check_mode, "answered from the cache of the old session's command"


def test_ids_go_on_across_queues_from_a_random_start():
    first, second = CommandQueue(), CommandQueue()
    a = first.submit("HOME").id
    b = second.submit("HOME").id
    c = first.submit("JOG", ("X", "1", "300")).id
    assert 0 < a < b < c
    assert first.heartbeat([]).pop().id > c
